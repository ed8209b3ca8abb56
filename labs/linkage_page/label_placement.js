// Where the joints' names go on the linkage page, pose by pose (linkage_page.js calls it on every
// redraw): never over one another, and off the joints' circles, the bars and the arrows where room
// allows. The ideas of numlab's static scenes (labs/scenes/label_placement.*), redone in the page:
//
//  1. candidates around each joint: 16 directions, the one the name prefers first (away from the
//     bars it is tied to), then alternately either side of it; on rings of growing distance from
//     the joint's circle, the nearest first;
//  2. a candidate whose box comes nearer than `apart` to a name already placed is refused; the
//     others score their clearance, the smallest gap between the box and anything drawn (the
//     joints' circles, the bars with their width, the boxes of the ground pivots, the arrows less a
//     bonus, and the frame's edges);
//  3. the candidate with the largest clearance, capped at `enough`, wins: among the clear ones the
//     nearest ring and then the direction nearest the preferred one; when every candidate of the
//     usual rings is refused, rings farther out are tried until one is not;
//  4. the names are placed one after the other, in the joints' order.
//
// Coordinates are the drawing's (SVG user units, y down); boxes are axis-aligned, given by their
// centre and half extents. The caller fills the pose's joints, preferred directions and obstacles
// into the placer's arrays, then calls place(); the placer allocates nothing per pose.
const numlabLabels = (function () {
  'use strict';

  // The gap between two boxes (0 when they touch or overlap).
  function boxGap(ax, ay, ahx, ahy, bx, by, bhx, bhy) {
    const dx = Math.max(Math.abs(ax - bx) - ahx - bhx, 0), dy = Math.max(Math.abs(ay - by) - ahy - bhy, 0);
    return Math.hypot(dx, dy);
  }
  function pointBoxDistance(px, py, cx, cy, hx, hy) {
    return Math.hypot(Math.max(Math.abs(px - cx) - hx, 0), Math.max(Math.abs(py - cy) - hy, 0));
  }
  function pointSegmentDistance(px, py, ax, ay, bx, by) {
    const dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    const t = l2 > 0 ? Math.min(1, Math.max(0, ((px - ax) * dx + (py - ay) * dy) / l2)) : 0;
    return Math.hypot(ax + t * dx - px, ay + t * dy - py);
  }
  // Whether the segment a-b passes through the box (Liang-Barsky clipping to t in [0, 1]): each axis
  // narrows the segment's span [first, last] to the box's slab, or finds it outside.
  let first = 0, last = 1;
  function clip(a, d, low, high) {
    if (d === 0) return a >= low && a <= high;
    const t0 = (low - a) / d, t1 = (high - a) / d;
    first = Math.max(first, Math.min(t0, t1));
    last = Math.min(last, Math.max(t0, t1));
    return true;
  }
  function segmentMeetsBox(cx, cy, hx, hy, ax, ay, bx, by) {
    first = 0; last = 1;
    return clip(ax, bx - ax, cx - hx, cx + hx) && clip(ay, by - ay, cy - hy, cy + hy) && first <= last;
  }
  // The distance from a box to a segment (0 when they meet).
  function boxSegmentDistance(cx, cy, hx, hy, ax, ay, bx, by) {
    if (segmentMeetsBox(cx, cy, hx, hy, ax, ay, bx, by)) return 0;
    let d = Math.min(pointBoxDistance(ax, ay, cx, cy, hx, hy), pointBoxDistance(bx, by, cx, cy, hx, hy));
    d = Math.min(d, pointSegmentDistance(cx - hx, cy - hy, ax, ay, bx, by), pointSegmentDistance(cx + hx, cy - hy, ax, ay, bx, by));
    return Math.min(d, pointSegmentDistance(cx - hx, cy + hy, ax, ay, bx, by), pointSegmentDistance(cx + hx, cy + hy, ax, ay, bx, by));
  }

  // A placer for names of half extents hw[k], hh[k] around joints' circles of `radius`, in a
  // drawing whose unit is `unit`; room for `most` obstacles of each kind.
  function placer(hw, hh, radius, unit, most) {
    const n = hw.length;
    const enough = 1.5 * unit, apart = 0.3 * unit, arrowBonus = 1.0 * unit;
    const rings = [0.5, 2.5, 5, 9, 14, 20, 28, 40, 56, 80].map(function (g) { return g * unit; });
    const usualRings = 4;
    const turns = [0];  // 1. the 16 directions as turns from the preferred one: 0, +-22.5, +-45, ..., 180 deg
    for (let k = 1; k < 8; ++k) turns.push(k * Math.PI / 8, -k * Math.PI / 8);
    turns.push(Math.PI);
    const cosTurn = turns.map(Math.cos), sinTurn = turns.map(Math.sin);
    const p = {
      ax: new Float64Array(n), ay: new Float64Array(n),  // the joints (set per pose)
      px: new Float64Array(n), py: new Float64Array(n),  // the preferred directions, unit vectors
      cx: new Float64Array(n), cy: new Float64Array(n),  // the names' centres place() finds
      segments: new Float64Array(5 * most), segmentCount: 0,  // x1 y1 x2 y2 reach
      discs: new Float64Array(3 * most), discCount: 0,  // x y radius
      boxes: new Float64Array(4 * most), boxCount: 0,  // cx cy hx hy
      frame: [-Infinity, -Infinity, Infinity, Infinity]  // x0 y0 x1 y1
    };
    p.clear = function () { p.segmentCount = 0; p.discCount = 0; p.boxCount = 0; };
    p.segment = function (x1, y1, x2, y2, halfWidth, arrow) {
      if (p.segmentCount >= most) return;
      const s = 5 * p.segmentCount++;
      p.segments[s] = x1; p.segments[s + 1] = y1; p.segments[s + 2] = x2; p.segments[s + 3] = y2;
      p.segments[s + 4] = halfWidth - (arrow ? arrowBonus : 0);
    };
    p.disc = function (x, y, r) {
      if (p.discCount >= most) return;
      const s = 3 * p.discCount++;
      p.discs[s] = x; p.discs[s + 1] = y; p.discs[s + 2] = r;
    };
    p.box = function (x, y, hx, hy) {
      if (p.boxCount >= most) return;
      const s = 4 * p.boxCount++;
      p.boxes[s] = x; p.boxes[s + 1] = y; p.boxes[s + 2] = hx; p.boxes[s + 3] = hy;
    };

    // 2. The clearance of a box for name k, given the names 0 .. k-1 placed: -Infinity if refused.
    function clearance(k, x, y) {
      const hx = hw[k], hy = hh[k];
      let gap = enough;
      for (let o = 0; o < k; ++o) {
        const g = boxGap(x, y, hx, hy, p.cx[o], p.cy[o], hw[o], hh[o]);
        if (g < apart) return -Infinity;
        gap = Math.min(gap, g);
      }
      for (let s = 0; s < 3 * p.discCount; s += 3) {
        gap = Math.min(gap, pointBoxDistance(p.discs[s], p.discs[s + 1], x, y, hx, hy) - p.discs[s + 2]);
      }
      for (let s = 0; s < 4 * p.boxCount; s += 4) {
        gap = Math.min(gap, boxGap(x, y, hx, hy, p.boxes[s], p.boxes[s + 1], p.boxes[s + 2], p.boxes[s + 3]));
      }
      for (let s = 0; s < 5 * p.segmentCount; s += 5) {
        const x1 = p.segments[s], y1 = p.segments[s + 1], x2 = p.segments[s + 2], y2 = p.segments[s + 3], reach = p.segments[s + 4];
        // A segment whose own box is already farther than the gap cannot lower it.
        const around = boxGap(x, y, hx, hy, (x1 + x2) / 2, (y1 + y2) / 2, Math.abs(x2 - x1) / 2, Math.abs(y2 - y1) / 2);
        if (around - reach >= gap) continue;
        gap = Math.min(gap, boxSegmentDistance(x, y, hx, hy, x1, y1, x2, y2) - reach);
      }
      const f = p.frame;
      return Math.min(gap, x - hx - f[0], y - hy - f[1], f[2] - x - hx, f[3] - y - hy);
    }
    // 1 and 3. Name k: the best candidate, nearest ring first, then the directions in turn.
    function placeOne(k) {
      let best = -Infinity;
      p.cx[k] = p.ax[k] + p.px[k] * (radius + rings[0] + hh[k]);  // where it goes if every candidate is refused
      p.cy[k] = p.ay[k] + p.py[k] * (radius + rings[0] + hh[k]);
      for (let r = 0; r < rings.length; ++r) {
        if (r >= usualRings && best > -Infinity) return;
        for (let d = 0; d < turns.length; ++d) {
          const dx = p.px[k] * cosTurn[d] - p.py[k] * sinTurn[d], dy = p.px[k] * sinTurn[d] + p.py[k] * cosTurn[d];
          const alongX = Math.abs(dx) > 1e-12 ? hw[k] / Math.abs(dx) : Infinity;
          const alongY = Math.abs(dy) > 1e-12 ? hh[k] / Math.abs(dy) : Infinity;
          const t = radius + rings[r] + Math.min(alongX, alongY);
          const x = p.ax[k] + dx * t, y = p.ay[k] + dy * t;
          const score = clearance(k, x, y);
          if (score > best + 1e-9 * unit) { best = score; p.cx[k] = x; p.cy[k] = y; }
          if (best >= enough) return;
        }
      }
    }
    // 4. Every name, in order.
    p.place = function () { for (let k = 0; k < n; ++k) placeOne(k); };
    return p;
  }

  return {placer: placer};
})();
