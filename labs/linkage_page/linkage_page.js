// The linkage page's script (numlab mechanism ... --html; docs/mechanisms.md "A linkage you can
// drag"). Written for numlab, no library: it reads the JSON numlab embedded in the page, builds the
// scene once, and moves it to the pose the slider picks. Without it the page shows numlab's static
// SVG of one pose and the table of every pose.
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('linkage-data').textContent);
  const live = document.getElementById('live');
  const cols = data.columns;
  const driverColumn = data.driver_column;
  const drivers = cols[driverColumn];
  const count = drivers.length;
  const degrees = /_deg$/.test(driverColumn);
  const unit = degrees ? ' deg' : '';
  const crank = data.driver.kind === 'crank';
  const per = {crank: 'radian of crank', motor: 'radian of the motor\'s angle', slider: 'unit of slider travel',
               actuator: 'unit of the actuator\'s length'}[data.driver.kind] || 'unit of the driver';
  const joints = data.joints;
  const svgNS = 'http://www.w3.org/2000/svg';
  const reducedMotion = window.matchMedia && window.matchMedia('(prefers-reduced-motion: reduce)').matches;

  // 1. Per pose: each joint's place and velocity from the columns, and whether the pose assembled.
  const xs = joints.map(function (j) { return cols['x_' + j.name]; });
  const ys = joints.map(function (j) { return cols['y_' + j.name]; });
  const vxs = joints.map(function (j) { return cols['vx_' + j.name] || null; });
  const vys = joints.map(function (j) { return cols['vy_' + j.name] || null; });
  const statuses = cols.status || [];
  const muColumns = Object.keys(cols).filter(function (name) { return name.indexOf('mu_') === 0; });
  const torqueColumn = cols.driver_torque ? 'driver_torque' : cols.driver_force ? 'driver_force' : null;
  const window40to140 = data.transmission_window || [40, 140];
  function assembled(i) {
    if (statuses[i] !== 'converged') return false;
    for (let j = 0; j < joints.length; ++j) {
      if (xs[j][i] === null || ys[j][i] === null) return false;
    }
    return true;
  }
  const ok = [];
  for (let i = 0; i < count; ++i) ok.push(assembled(i));
  const firstOk = ok.indexOf(true);
  if (firstOk < 0) {
    live.textContent = 'No pose of this sweep assembled: nothing to scrub (the table below lists the attempts).';
    return;
  }
  document.documentElement.classList.add('linkage-live');
  document.getElementById('lede').textContent =
    'Drag the slider (or use the arrow keys, Home and End on it) to scrub the solved poses; Play runs through them.';

  // 2. The frame: every assembled pose's joints, then the velocity arrows' tips (one scale for the
  // whole sweep, the fastest joint's arrow 20% of the frame's larger side, so arrows compare).
  let minX = Infinity, maxX = -Infinity, minY = Infinity, maxY = -Infinity;
  function include(x, y) {
    minX = Math.min(minX, x); maxX = Math.max(maxX, x); minY = Math.min(minY, y); maxY = Math.max(maxY, y);
  }
  for (let i = 0; i < count; ++i) {
    if (!ok[i]) continue;
    for (let j = 0; j < joints.length; ++j) include(xs[j][i], ys[j][i]);
  }
  const side = Math.max(maxX - minX, maxY - minY) || 1;
  const u = side / 100;  // one unit of drawing: strokes, circles and names are sized in it
  let fastest = 0;
  for (let i = 0; i < count; ++i) {
    if (!ok[i]) continue;
    for (let j = 0; j < joints.length; ++j) {
      if (vxs[j] && vxs[j][i] !== null && vys[j][i] !== null) fastest = Math.max(fastest, Math.hypot(vxs[j][i], vys[j][i]));
    }
  }
  const arrowScale = fastest > 0 ? 0.2 * side / fastest : 0;
  if (arrowScale > 0) {
    for (let i = 0; i < count; ++i) {
      if (!ok[i]) continue;
      for (let j = 0; j < joints.length; ++j) {
        if (vxs[j] && vxs[j][i] !== null) include(xs[j][i] + vxs[j][i] * arrowScale, ys[j][i] + vys[j][i] * arrowScale);
      }
    }
  }
  // 2b. The forces, for a file with [[load]]s: each load as the file gives it (a force or a mass's
  // weight at its joint, a torque on a link or body) and each support's reaction at the pose, the
  // CSV's reaction_S_x, reaction_S_y (the force the ground, or a slider's guide, exerts on the
  // mechanism at S). One scale for the sweep: the largest force of the sweep (a load, or a reaction
  // where the statics are in equilibrium) a quarter of the frame's larger side. Arrows start at their joint.
  const loads = data.loads || [];
  const hasForces = loads.length > 0;
  const statics = cols.statics || [];
  const supportJoint = [], supportName = [], reactionX = [], reactionY = [];
  (hasForces ? data.csv_columns : []).forEach(function (c) {
    const m = /^reaction_(.+)_x$/.exec(c);
    const j = m ? joints.findIndex(function (joint) { return joint.name === m[1]; }) : -1;
    if (j < 0 || !cols['reaction_' + m[1] + '_y']) return;
    supportJoint.push(j); supportName.push(m[1]);
    reactionX.push(cols[c]); reactionY.push(cols['reaction_' + m[1] + '_y']);
  });
  function inEquilibrium(i) { return ok[i] && statics[i] === 'equilibrium'; }
  function finiteForce(x, y) { return x !== null && y !== null && isFinite(x) && isFinite(y); }
  let largestForce = 0;
  loads.forEach(function (l) { if (l.force) largestForce = Math.max(largestForce, Math.hypot(l.force[0], l.force[1])); });
  for (let i = 0; i < count; ++i) {
    if (!inEquilibrium(i)) continue;
    for (let s = 0; s < supportJoint.length; ++s) {
      if (finiteForce(reactionX[s][i], reactionY[s][i])) largestForce = Math.max(largestForce, Math.hypot(reactionX[s][i], reactionY[s][i]));
    }
  }
  const forceScale = largestForce > 0 ? 0.25 * side / largestForce : 0;  // drawing units per newton
  for (let i = 0; i < count && forceScale > 0; ++i) {
    if (!ok[i]) continue;
    loads.forEach(function (l) { if (l.force) include(xs[l.joint][i] + l.force[0] * forceScale, ys[l.joint][i] + l.force[1] * forceScale); });
    for (let s = 0; s < supportJoint.length && inEquilibrium(i); ++s) {
      const j = supportJoint[s];
      if (finiteForce(reactionX[s][i], reactionY[s][i])) include(xs[j][i] + reactionX[s][i] * forceScale, ys[j][i] + reactionY[s][i] * forceScale);
    }
  }
  const pad = 9 * u;
  const view = [minX - pad, -maxY - pad, maxX - minX + 2 * pad, maxY - minY + 2 * pad];

  function element(name, attributes, parent) {
    const e = document.createElementNS(svgNS, name);
    for (const key in attributes) e.setAttribute(key, attributes[key]);
    if (parent) parent.appendChild(e);
    return e;
  }
  function html(name, attributes, parent, text) {
    const e = document.createElement(name);
    for (const key in attributes) e.setAttribute(key, attributes[key]);
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  function number(v, digits) {
    if (v === null || v === undefined) return '\u2013';
    if (typeof v !== 'number') return String(v);
    const a = Math.abs(v);
    if (a !== 0 && (a >= 1e7 || a < 1e-4)) return v.toExponential((digits || 7) - 1);
    return String(Number(v.toPrecision(digits || 7)));
  }
  function driverText(i) {
    return (crank ? 'crank ' : driverColumn + ' ') + number(drivers[i], 10) + unit;
  }

  // 3. The scene, built once: slider guides, joint paths, ground pivots, bodies, links, slider
  // blocks, joints, velocity arrows, names; update() moves them.
  const heading = html('h2', {id: 'scene-heading'}, live, 'The linkage at a pose of the sweep');
  const svg = element('svg', {id: 'scene', viewBox: view.join(' '), role: 'img', 'aria-labelledby': 'scene-heading scene-pose'});
  const stage = html('div', {class: 'stage'}, live);
  const left = html('div', {class: 'stage-scene'}, stage);
  const right = html('div', {class: 'stage-readout'}, stage);
  left.appendChild(svg);
  const defs = element('defs', {}, svg);
  const marker = element('marker', {id: 'live-velocity-head', viewBox: '0 0 10 10', refX: 8, refY: 5, markerWidth: 4,
                                    markerHeight: 4, orient: 'auto'}, defs);
  element('path', {d: 'M 0 0 L 10 5 L 0 10 z', class: 'arrow-head'}, marker);
  ['load', 'reaction'].forEach(function (kind) {
    const m = element('marker', {id: 'live-' + kind + '-head', viewBox: '0 0 10 10', refX: 8, refY: 5, markerWidth: 4,
                                 markerHeight: 4, orient: 'auto'}, defs);
    element('path', {d: 'M 0 0 L 10 5 L 0 10 z', class: kind + '-head'}, m);
  });
  const guideLayer = element('g', {class: 'guides'}, svg);
  const pathLayer = element('g', {class: 'paths'}, svg);
  const groundLayer = element('g', {class: 'ground'}, svg);
  const bodyLayer = element('g', {class: 'bodies'}, svg);
  const linkLayer = element('g', {class: 'links'}, svg);
  const sliderLayer = element('g', {class: 'sliders'}, svg);
  const jointLayer = element('g', {class: 'joints'}, svg);
  const arrowLayer = element('g', {class: 'arrows'}, svg);
  const forceLayer = element('g', {class: 'forces', id: 'forces'}, svg);
  if (forceScale > 0) forceLayer.setAttribute('data-newtons-per-unit', 1 / forceScale);  // the scale, in full
  const nameLayer = element('g', {class: 'names'}, svg);
  const notAssembled = element('text', {x: view[0] + view[2] / 2, y: view[1] + 6 * u, 'font-size': 5 * u,
                                        class: 'not-assembled', 'text-anchor': 'middle'}, svg);
  svg.style.setProperty('--u', u);

  const isCrank = function (a, b) {  // the crank's link, drawn red
    const p = data.driver.pivot, q = data.driver.joint;
    return crank && ((a === p && b === q) || (a === q && b === p));
  };
  data.sliders.forEach(function (s) {
    if (s.line) return;  // a slot in a moving body: its line moves with it
    const a = s.angle_deg * Math.PI / 180, reach = 2 * side;
    element('line', {x1: s.through[0] - reach * Math.cos(a), y1: -(s.through[1] - reach * Math.sin(a)),
                     x2: s.through[0] + reach * Math.cos(a), y2: -(s.through[1] + reach * Math.sin(a)),
                     'stroke-width': 0.4 * u, 'stroke-dasharray': (3 * u) + ' ' + (1.5 * u), class: 'guide'}, guideLayer);
  });
  joints.forEach(function (joint, j) {
    if (joint.ground) return;
    let d = '', pen = 'M';
    for (let i = 0; i < count; ++i) {
      if (!ok[i]) { pen = 'M'; continue; }
      d += pen + ' ' + xs[j][i] + ' ' + (-ys[j][i]) + ' ';
      pen = 'L';
    }
    element('path', {d: d, class: 'path', 'stroke-width': 0.45 * u, 'stroke-dasharray': (2 * u) + ' ' + (1.5 * u)}, pathLayer);
  });
  joints.forEach(function (joint, j) {
    if (!joint.ground) return;
    const x = xs[j][firstOk], y = -ys[j][firstOk];
    let d = 'M ' + x + ' ' + y + ' l ' + (-3 * u) + ' ' + (5 * u) + ' h ' + (6 * u) + ' z M ' + (x - 5 * u) + ' ' + (y + 5 * u) + ' h ' + (10 * u);
    for (let k = 0; k < 5; ++k) d += ' M ' + (x - 4 * u + 2 * k * u) + ' ' + (y + 5 * u) + ' l ' + (-1.5 * u) + ' ' + (2 * u);
    element('path', {d: d, class: 'pivot', 'stroke-width': 0.4 * u}, groundLayer);
  });

  // A body's outline: the convex hull of its joints at the first assembled pose (a rigid body keeps
  // that order); all on one line, a bar between its two extreme joints.
  function hull(indices) {
    const pts = indices.map(function (j) { return [xs[j][firstOk], ys[j][firstOk], j]; })
      .sort(function (a, b) { return a[0] - b[0] || a[1] - b[1]; });
    const cross = function (o, a, b) { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); };
    const lower = [], upper = [];
    pts.forEach(function (p) {
      while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], p) <= 1e-12 * side * side) lower.pop();
      lower.push(p);
    });
    pts.slice().reverse().forEach(function (p) {
      while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], p) <= 1e-12 * side * side) upper.pop();
      upper.push(p);
    });
    return lower.slice(0, -1).concat(upper.slice(0, -1)).map(function (p) { return p[2]; });
  }
  const bodies = data.bodies.map(function (body) {
    const outline = hull(body.joints);
    const driven = crank && body.joints.indexOf(data.driver.pivot) >= 0 && body.joints.indexOf(data.driver.joint) >= 0;
    const shape = outline.length >= 3
      ? element('polygon', {class: 'body' + (driven ? ' driven' : ''), 'stroke-width': 1.2 * u}, bodyLayer)
      : element('line', {class: 'bar' + (driven ? ' driven' : ''), 'stroke-width': 2.4 * u}, bodyLayer);
    return {outline: outline, shape: shape};
  });
  const links = data.links.map(function (link) {
    const heavy = isCrank(link[0], link[1]);
    return {a: link[0], b: link[1], shape: element('line', {class: 'link' + (heavy ? ' driven' : ''), 'stroke-width': (heavy ? 3 : 2) * u}, linkLayer)};
  });
  // An actuator: a thick cylinder from its first joint and a thin rod on to its second, half each.
  const isJoint = function (j) { return Number.isInteger(j) && j >= 0 && j < joints.length; };
  const actuator = data.driver.kind === 'actuator' && isJoint(data.driver.from) && isJoint(data.driver.joint)
    ? {cylinder: element('line', {class: 'link driven', 'stroke-width': 3.5 * u}, linkLayer),
       rod: element('line', {class: 'link driven', 'stroke-width': 1.2 * u}, linkLayer)}
    : null;
  const sliders = data.sliders.map(function (s, k) {
    const g = element('g', {class: 'slider-block'}, sliderLayer);
    element('rect', {x: -4 * u, y: -2.5 * u, width: 8 * u, height: 5 * u, 'stroke-width': 0.5 * u,
                     class: data.driver.slider === k && !crank ? 'driven' : ''}, g);
    return {slider: s, g: g};
  });
  const circles = joints.map(function (joint) {
    return element('circle', {r: 1.6 * u, 'stroke-width': 0.7 * u, class: 'joint', 'data-joint': joint.name}, jointLayer);
  });
  const arrows = joints.map(function (joint) {
    if (joint.ground || !vxs[joints.indexOf(joint)]) return null;
    return element('line', {class: 'velocity', 'stroke-width': 0.7 * u, 'marker-end': 'url(#live-velocity-head)'}, arrowLayer);
  });
  // The forces' shapes: a line per force load and per support's reaction, an arc per torque load
  // (counter-clockwise or clockwise as its sign), each with a title saying what it is.
  function loadText(l) {
    if (l.kind === 'torque') {
      return 'torque ' + number(l.torque, 10) + ' N\u00b7(length unit) on ' + l.link + ' (' + (l.torque >= 0 ? 'counter-clockwise' : 'clockwise') + ')';
    }
    const f = '(' + number(l.force[0], 10) + ', ' + number(l.force[1], 10) + ') N';
    return l.kind === 'mass' ? 'mass ' + number(l.mass, 10) + ' kg at ' + joints[l.joint].name + ': its weight ' + f +
      ' (g = ' + number(l.gravity, 10) + ' m/s\u00b2)' : 'force ' + f + ' at ' + joints[l.joint].name;
  }
  function supportText(s) {
    return joints[supportJoint[s]].ground ? 'the force the ground exerts on the mechanism at ' + supportName[s]
      : 'the force the guide of ' + supportName[s] + '\'s slider exerts on it (normal to the guide)';
  }
  const loadShapes = loads.map(function (l, k) {
    const e = l.kind === 'torque'
      ? element('path', {class: 'torque-load', 'data-load': k, 'data-torque': l.torque, 'stroke-width': 0.7 * u,
                         'marker-end': 'url(#live-load-head)'}, forceLayer)
      : element('line', {class: 'load', 'data-load': k, 'stroke-width': 0.8 * u, 'marker-end': 'url(#live-load-head)'}, forceLayer);
    element('title', {}, e).textContent = 'load: ' + loadText(l);
    return e;
  });
  const reactionShapes = supportName.map(function (name, s) {
    const e = element('line', {class: 'reaction', 'data-support': name, 'stroke-width': 0.8 * u,
                               'marker-end': 'url(#live-reaction-head)'}, forceLayer);
    element('title', {}, e).textContent = 'reaction: ' + supportText(s);
    return e;
  });
  const forceEnds = new Float64Array(4 * (loads.length + supportName.length));  // x1 y1 x2 y2 of each line drawn, NaN if none
  const names = joints.map(function (joint) {
    const t = element('text', {'font-size': 4.5 * u, 'text-anchor': 'middle', 'dominant-baseline': 'central'}, nameLayer);
    t.textContent = joint.name;
    return t;
  });
  // The names' boxes, measured once (a name keeps its size): half extents and the box's centre
  // from the text's anchor; a rough size where the browser measures nothing (not laid out).
  const nameBoxes = names.map(function (t) {
    let b = null;
    try { b = t.getBBox(); } catch (e) { b = null; }
    if (!b || !(b.width > 0)) b = {x: -1.35 * u * t.textContent.length, y: -2.6 * u, width: 2.7 * u * t.textContent.length, height: 5.2 * u};
    return {hx: b.width / 2, hy: b.height / 2, ox: b.x + b.width / 2, oy: b.y + b.height / 2};
  });
  const jointRadius = 1.6 * u + 0.35 * u;  // the circle with half its stroke
  const outlineSides = bodies.reduce(function (total, b) { return total + b.outline.length; }, 0);
  const labels = numlabLabels.placer(nameBoxes.map(function (b) { return b.hx; }), nameBoxes.map(function (b) { return b.hy; }),
                                     jointRadius, u, links.length + outlineSides + 2 * joints.length + sliders.length + 2 +
                                     loads.length + supportName.length);
  labels.frame = [view[0], view[1], view[0] + view[2], view[1] + view[3]];
  const neighbours = joints.map(function () { return []; });
  data.links.forEach(function (l) { neighbours[l[0]].push(l[1]); neighbours[l[1]].push(l[0]); });
  if (actuator) { neighbours[data.driver.from].push(data.driver.joint); neighbours[data.driver.joint].push(data.driver.from); }
  data.bodies.forEach(function (b) {
    b.joints.forEach(function (a) { b.joints.forEach(function (c) { if (a !== c) neighbours[a].push(c); }); });
  });
  const caption = html('p', {class: 'scene-caption'}, null,
    'Dashed: each moving joint\'s path over the ' + ok.filter(Boolean).length + ' assembled poses; red: the driver. ' +
    (arrowScale > 0 ? 'Green arrows: each joint\'s velocity per ' + per + ', one scale for the whole sweep (an arrow 1 ' +
     'unit long stands for ' + number(1 / arrowScale, 3) + ' units per ' + per + ').' : 'No velocities in these numbers: no arrows.') +
    (data.driver.kind === 'actuator' ? ' The actuator is the red cylinder and rod.' : ''));
  caption.id = 'scene-caption';

  // 4. The controls: first, previous, play, next, last, and the slider with its marks.
  const controls = html('div', {class: 'controls', role: 'group', 'aria-label': 'Pose controls'}, left);
  function button(id, text, label) {
    const b = html('button', {type: 'button', id: id, 'aria-label': label, title: label}, controls, text);
    return b;
  }
  const first = button('pose-first', '|\u25c0', 'First pose');
  const previous = button('pose-previous', '\u25c0', 'Previous pose');
  const play = button('pose-play', 'Play', 'Play through the poses');
  play.setAttribute('aria-pressed', 'false');
  const next = button('pose-next', '\u25b6', 'Next pose');
  const last = button('pose-last', '\u25b6|', 'Last pose');
  const track = html('div', {class: 'track'}, left);
  html('label', {for: 'pose-slider', id: 'pose-slider-label'}, track, (crank ? 'Crank angle' : driverColumn) +
       ' (' + number(drivers[0], 10) + ' to ' + number(drivers[count - 1], 10) + unit + ', ' + count + ' poses)');
  const slider = html('input', {type: 'range', id: 'pose-slider', min: 0, max: count - 1, step: 1, value: firstOk}, track);
  const markBar = html('div', {class: 'marks', 'aria-hidden': 'true'}, track);
  const d0 = drivers[0], d1 = drivers[count - 1];
  function share(d) { return d1 === d0 ? 0 : Math.min(1, Math.max(0, (d - d0) / (d1 - d0))); }
  function place(e, f) { e.style.left = 'calc(8px + (100% - 16px) * ' + f + ')'; }
  for (let i = 0; i < count; ++i) {  // runs of poses that did not assemble, shaded
    if (ok[i] || (i > 0 && !ok[i - 1])) continue;
    let k = i;
    while (k + 1 < count && !ok[k + 1]) ++k;
    const band = html('span', {class: 'band', title: 'did not assemble: ' + driverText(i) + ' to ' + driverText(k)}, markBar);
    place(band, count > 1 ? i / (count - 1) : 0);
    band.style.width = 'calc((100% - 16px) * ' + (count > 1 ? (k - i + 1) / (count - 1) : 1) + ')';
  }
  function nearestPose(d) {
    let best = firstOk;
    for (let i = 0; i < count; ++i) if (ok[i] && Math.abs(drivers[i] - d) < Math.abs(drivers[best] - d)) best = i;
    return best;
  }
  const markList = html('ul', {class: 'mark-list', id: 'mark-list'}, left);
  data.marks.forEach(function (m) {
    const tick = html('span', {class: 'tick ' + m.kind, title: m.text}, markBar);
    place(tick, share(m.driver));
    const item = html('li', {class: m.kind}, markList);
    const go = html('button', {type: 'button', class: 'go'}, item, 'go to ' + number(m.driver, 6) + unit);
    go.addEventListener('click', function () { show(nearestPose(m.driver)); slider.focus(); });
    item.appendChild(document.createTextNode(' ' + m.text));
  });
  if (!data.marks.length) html('li', {class: 'none'}, markList, 'No assembly limit or branch crossing in this sweep.');

  // Play: at the crank's real speed when --speed gave one, else at a fixed rate said here.
  const step = count > 1 ? Math.abs(drivers[1] - drivers[0]) || 1 : 1;
  let rate;  // poses per second
  let rateText;
  if (reducedMotion) {
    rate = 2;
    rateText = 'Your system asks for reduced motion: Play shows two poses a second.';
  } else if (crank && degrees && data.speed_rad_s) {
    rate = Math.abs(data.speed_rad_s) * 180 / Math.PI / step;
    rateText = 'Play runs at the crank\'s real speed, ' + number(data.speed_rad_s, 6) + ' rad/s (' +
      number(data.speed_rad_s * 30 / Math.PI, 6) + ' rpm), from --speed: one turn in ' + number(2 * Math.PI / Math.abs(data.speed_rad_s), 4) + ' s.';
  } else if (crank && degrees) {
    rate = 90 / step;
    rateText = 'Play runs at a fixed 90 deg of crank a second (a turn in 4 s): no --speed was given.';
  } else {
    rate = Math.max(1, count / 4);
    rateText = 'Play runs through the sweep in 4 s (a fixed rate).';
  }
  html('p', {class: 'play-rate', id: 'play-rate'}, left, rateText);

  // The forces' switch (a checkbox: Space toggles it), their scale and why a pose has no reactions.
  let forcesOn = hasForces, forceNote = null;
  if (hasForces) {
    const toggle = html('p', {class: 'force-toggle'}, left);
    const check = html('input', {type: 'checkbox', id: 'show-forces'}, toggle);
    check.checked = true;
    html('label', {for: 'show-forces'}, toggle, ' Show the forces: the loads (purple) and the supports\' reactions (orange)');
    check.addEventListener('change', function () {
      forcesOn = check.checked;
      forceLayer.style.display = forcesOn ? '' : 'none';
      show(shown);  // the names placed again, clear of the arrows or not
    });
    html('p', {class: 'force-scale', id: 'force-scale'}, left, forceScale > 0
      ? 'Force arrows start at their joint; an arrow 1 unit of length long stands for ' + number(1 / forceScale, 6) +
        ' N (the largest force of the sweep, ' + number(largestForce, 6) + ' N, is a quarter of the frame\'s larger side). ' +
        'A reaction is ' + supportName.map(function (name, s) { return supportText(s); }).join('; ') +
        '.' + (loads.some(function (l) { return l.kind === 'torque'; }) ? ' A torque load is a curved arrow on its link, turning its way.' : '')
      : 'The loads and reactions are all zero: no force arrow to draw.');
    forceNote = html('p', {class: 'force-note', id: 'force-note', 'aria-live': 'polite'}, left);
  }
  left.appendChild(caption);

  // 5. The readout: the pose's numbers, each carrying its column and full value.
  const readout = html('div', {class: 'readout', id: 'readout'}, right);
  const status = html('p', {id: 'scene-pose', class: 'pose-line', 'aria-live': 'polite'}, readout);
  const facts = html('dl', {class: 'facts'}, readout);
  function fact(label, column) {
    if (!cols[column]) return null;
    html('dt', {}, facts, label);
    return html('dd', {'data-col': column}, facts);
  }
  const factCells = [
    [fact(crank ? 'crank angle (deg)' : driverColumn, driverColumn), driverColumn],
    [fact('status', 'status'), 'status'],
    [fact('Newton iterations', 'iterations'), 'iterations'],
    [fact('||f||\u221e (residual)', 'residual_inf'), 'residual_inf'],
    [fact('\u03ba(J)', 'condition'), 'condition'],
    [fact('branch kept', 'branch_kept'), 'branch_kept']
  ];
  muColumns.forEach(function (c) {
    factCells.push([fact('transmission angle at ' + c.slice(3) + ' (deg)', c), c]);
  });
  if (torqueColumn) {
    factCells.push([fact(torqueColumn === 'driver_torque' ? 'driver torque (CCW +)' : 'driver force', torqueColumn), torqueColumn]);
    factCells.push([fact('statics', 'statics'), 'statics']);
  }
  // The reactions at the pose (N): x, y from the CSV, and their magnitude; then the loads.
  const reactionCells = [];
  if (hasForces) {
    const table = html('table', {class: 'reaction-table', id: 'reaction-table'}, readout);
    html('caption', {}, table, 'Reactions at the supports (N): the force on the mechanism at each');
    const top = html('tr', {}, html('thead', {}, table));
    ['support', 'x', 'y', '|F|'].forEach(function (h) { html('th', {scope: 'col'}, top, h); });
    const rows = html('tbody', {}, table);
    supportName.forEach(function (name, s) {
      const row = html('tr', {}, rows);
      html('th', {scope: 'row', title: supportText(s)}, row, name + (joints[supportJoint[s]].ground ? ' (ground)' : ' (guide)'));
      reactionCells.push([html('td', {'data-col': 'reaction_' + name + '_x'}, row), html('td', {'data-col': 'reaction_' + name + '_y'}, row),
                          html('td', {class: 'magnitude'}, row)]);
    });
    const list = html('ul', {class: 'load-list', id: 'load-list'}, readout);
    loads.forEach(function (l) { html('li', {}, list, 'load: ' + loadText(l)); });
  }
  const jointTable = html('table', {class: 'joint-table', id: 'joint-table'}, readout);
  const head = html('tr', {}, html('thead', {}, jointTable));
  const hasVelocity = vxs.some(Boolean);
  ['joint', 'x', 'y'].concat(hasVelocity ? ['vx', 'vy'] : []).forEach(function (h) { html('th', {scope: 'col'}, head, h); });
  const body = html('tbody', {}, jointTable);
  const jointCells = joints.map(function (joint) {
    const row = html('tr', {}, body);
    html('th', {scope: 'row'}, row, joint.name + (joint.ground ? ' (ground)' : ''));
    return ['x_', 'y_'].concat(hasVelocity ? ['vx_', 'vy_'] : []).map(function (prefix) {
      return [html('td', {'data-col': prefix + joint.name}, row), prefix + joint.name];
    });
  });

  // 6. Charts under the readout: kappa(J) (log scale) and the driver torque, with a cursor at the pose.
  const charts = [];
  function chart(column, label, log) {
    const values = cols[column];
    if (!values) return;
    const W = 600, H = 90, left = 60;
    let lo = Infinity, hi = -Infinity;
    const v = values.map(function (x) { return x === null ? null : log ? (x > 0 ? Math.log10(x) : null) : x; });
    v.forEach(function (x) { if (x !== null) { lo = Math.min(lo, x); hi = Math.max(hi, x); } });
    if (!isFinite(lo)) return;
    if (hi === lo) { hi += 1; lo -= 1; }
    const figure = html('figure', {class: 'chart'}, live);
    const c = element('svg', {viewBox: '0 0 ' + (W + left + 10) + ' ' + (H + 20), role: 'img', 'aria-label': label}, figure);
    const xOf = function (i) { return left + W * (count > 1 ? i / (count - 1) : 0); };
    const yOf = function (x) { return 5 + H * (1 - (x - lo) / (hi - lo)); };
    let d = '', pen = 'M';
    v.forEach(function (x, i) { if (x === null) { pen = 'M'; return; } d += pen + xOf(i).toFixed(1) + ' ' + yOf(x).toFixed(1) + ' '; pen = 'L'; });
    element('rect', {x: left, y: 5, width: W, height: H, class: 'frame'}, c);
    element('path', {d: d, class: 'series'}, c);
    const top = element('text', {x: left - 4, y: 12, 'text-anchor': 'end', class: 'axis'}, c);
    top.textContent = number(log ? Math.pow(10, hi) : hi, 4);
    const bottom = element('text', {x: left - 4, y: H + 5, 'text-anchor': 'end', class: 'axis'}, c);
    bottom.textContent = number(log ? Math.pow(10, lo) : lo, 4);
    const under = element('text', {x: left, y: H + 18, class: 'axis'}, c);
    under.textContent = number(d0, 6) + unit;
    const end = element('text', {x: left + W, y: H + 18, 'text-anchor': 'end', class: 'axis'}, c);
    end.textContent = number(d1, 6) + unit;
    const cursor = element('line', {y1: 5, y2: 5 + H, class: 'cursor'}, c);
    html('figcaption', {}, figure, label);
    charts.push({cursor: cursor, xOf: xOf});
  }
  chart('condition', '\u03ba(J) over the sweep (log scale); the line marks the pose shown', true);
  if (torqueColumn) chart(torqueColumn, (torqueColumn === 'driver_torque' ? 'driver torque' : 'driver force') + ' over the sweep; the line marks the pose shown', false);

  // 7. One pose: move every shape, fill the readout.
  let shown = -1;
  function xy(j, i) { return [xs[j][i], -ys[j][i]]; }
  function show(i) {
    i = Math.max(0, Math.min(count - 1, i | 0));
    shown = i;
    if (String(slider.value) !== String(i)) slider.value = i;
    const here = ok[i];
    svg.classList.toggle('stale', !here);
    notAssembled.textContent = here ? '' : 'This pose did not assemble (' + statuses[i] + '): the last assembled pose is drawn faded';
    const at = here ? i : lastDrawn;
    if (at >= 0) { drawForces(i, at); draw(at); }
    status.textContent = driverText(i) + ': ' + (statuses[i] || '') + (here ? '' : ' (not assembled)');
    slider.setAttribute('aria-valuetext', status.textContent);
    factCells.forEach(function (f) {
      if (!f[0]) return;
      const value = cols[f[1]][i];
      f[0].textContent = typeof value === 'number' ? number(value, f[1] === 'iterations' ? 10 : 7) : value === null ? '\u2013' : value;
      f[0].setAttribute('data-value', value === null ? '' : String(value));
      const mu = f[1].indexOf('mu_') === 0;
      f[0].classList.toggle('warn', mu && value !== null && (value < window40to140[0] || value > window40to140[1]));
    });
    jointCells.forEach(function (cells) {
      cells.forEach(function (c) {
        const value = cols[c[1]] ? cols[c[1]][i] : null;
        c[0].textContent = number(value, 8);
        c[0].setAttribute('data-value', value === null ? '' : String(value));
      });
    });
    reactionCells.forEach(function (cells, s) {
      const x = reactionX[s][i], y = reactionY[s][i], m = finiteForce(x, y) ? Math.hypot(x, y) : null;
      [x, y, m].forEach(function (value, c) {
        cells[c].textContent = number(value, 7);
        cells[c].setAttribute('data-value', value === null ? '' : String(value));
      });
    });
    if (forceNote) {
      forceNote.textContent = inEquilibrium(i) ? '' : 'No reactions at this pose: its statics are ' + (statics[i] || 'missing') +
        (statics[i] === 'singular' ? ' (J is singular: no finite driver load and reactions hold the loads; the CSV writes inf)'
          : ' (the pose did not assemble: the CSV writes nan)') + '.';
    }
    charts.forEach(function (c) { c.cursor.setAttribute('x1', c.xOf(i)); c.cursor.setAttribute('x2', c.xOf(i)); });
  }
  // The forces at pose i, on the joints drawn at pose `at` (the same pose, or the last assembled one:
  // there the loads are drawn and no reaction). Each line's ends go to forceEnds for the names.
  function drawForces(i, at) {
    forceEnds.fill(NaN);
    loads.forEach(function (l, k) {
      const shape = loadShapes[k];
      if (l.kind === 'torque') {  // an arc of 270 deg round the link's joints' centre (y down: counter-clockwise is sweep 0)
        let cx = 0, cy = 0;
        l.joints.forEach(function (j) { const p = xy(j, at); cx += p[0] / l.joints.length; cy += p[1] / l.joints.length; });
        const r = 4 * u, ccw = l.torque >= 0, a0 = (ccw ? 135 : 45) * Math.PI / 180, a1 = a0 + (ccw ? -1.5 : 1.5) * Math.PI;
        shape.setAttribute('d', 'M ' + (cx + r * Math.cos(a0)) + ' ' + (cy + r * Math.sin(a0)) + ' A ' + r + ' ' + r + ' 0 1 ' +
                           (ccw ? 0 : 1) + ' ' + (cx + r * Math.cos(a1)) + ' ' + (cy + r * Math.sin(a1)));
        return;
      }
      const p = xy(l.joint, at), q = [p[0] + l.force[0] * forceScale, p[1] - l.force[1] * forceScale];
      shape.setAttribute('x1', p[0]); shape.setAttribute('y1', p[1]); shape.setAttribute('x2', q[0]); shape.setAttribute('y2', q[1]);
      forceEnds.set([p[0], p[1], q[0], q[1]], 4 * k);
    });
    const equilibrium = inEquilibrium(i);
    reactionShapes.forEach(function (shape, s) {
      const fx = reactionX[s][i], fy = reactionY[s][i];
      const visible = equilibrium && finiteForce(fx, fy) && Math.hypot(fx, fy) > 0;
      shape.style.display = visible ? '' : 'none';
      if (!visible) return;
      const p = xy(supportJoint[s], i), q = [p[0] + fx * forceScale, p[1] - fy * forceScale];
      shape.setAttribute('x1', p[0]); shape.setAttribute('y1', p[1]); shape.setAttribute('x2', q[0]); shape.setAttribute('y2', q[1]);
      forceEnds.set([p[0], p[1], q[0], q[1]], 4 * (loads.length + s));
    });
  }
  let lastDrawn = -1;
  function draw(i) {
    lastDrawn = i;
    bodies.forEach(function (b) {
      if (b.outline.length >= 3) {
        b.shape.setAttribute('points', b.outline.map(function (j) { return xy(j, i).join(','); }).join(' '));
      } else if (b.outline.length === 2) {
        const p = xy(b.outline[0], i), q = xy(b.outline[1], i);
        b.shape.setAttribute('x1', p[0]); b.shape.setAttribute('y1', p[1]); b.shape.setAttribute('x2', q[0]); b.shape.setAttribute('y2', q[1]);
      }
    });
    links.forEach(function (l) {
      const p = xy(l.a, i), q = xy(l.b, i);
      l.shape.setAttribute('x1', p[0]); l.shape.setAttribute('y1', p[1]); l.shape.setAttribute('x2', q[0]); l.shape.setAttribute('y2', q[1]);
    });
    if (actuator) {
      const p = xy(data.driver.from, i), q = xy(data.driver.joint, i), m = [(p[0] + q[0]) / 2, (p[1] + q[1]) / 2];
      actuator.cylinder.setAttribute('x1', p[0]); actuator.cylinder.setAttribute('y1', p[1]);
      actuator.cylinder.setAttribute('x2', m[0]); actuator.cylinder.setAttribute('y2', m[1]);
      actuator.rod.setAttribute('x1', m[0]); actuator.rod.setAttribute('y1', m[1]);
      actuator.rod.setAttribute('x2', q[0]); actuator.rod.setAttribute('y2', q[1]);
    }
    sliders.forEach(function (s) {
      const p = xy(s.slider.joint, i);
      let angle = s.slider.angle_deg;
      if (s.slider.line) {
        const a = xy(s.slider.line[0], i), b = xy(s.slider.line[1], i);
        angle = -Math.atan2(b[1] - a[1], b[0] - a[0]) * 180 / Math.PI;
      }
      s.g.setAttribute('transform', 'translate(' + p[0] + ',' + p[1] + ') rotate(' + (-angle) + ')');
    });
    circles.forEach(function (c, j) { const p = xy(j, i); c.setAttribute('cx', p[0]); c.setAttribute('cy', p[1]); });
    arrows.forEach(function (a, j) {
      if (!a) return;
      const p = xy(j, i), vx = vxs[j][i], vy = vys[j][i];
      const visible = vx !== null && vy !== null && Math.hypot(vx, vy) > 0;
      a.style.display = visible ? '' : 'none';
      if (!visible) return;
      a.setAttribute('x1', p[0]); a.setAttribute('y1', p[1]);
      a.setAttribute('x2', p[0] + vx * arrowScale); a.setAttribute('y2', p[1] - vy * arrowScale);
    });
    placeNames(i);
  }
  // The names at pose i (label_placement.js): what they must keep clear of, each name's preferred
  // direction (away from the joints it is tied to; a ground pivot's beside and above its triangle),
  // then the placement, moved into the text elements.
  function placeNames(i) {
    labels.clear();
    links.forEach(function (l) {
      const p = xy(l.a, i), q = xy(l.b, i);
      labels.segment(p[0], p[1], q[0], q[1], (isCrank(l.a, l.b) ? 1.5 : 1) * u, false);
    });
    bodies.forEach(function (b) {
      const m = b.outline.length;
      if (m === 2) {
        const p = xy(b.outline[0], i), q = xy(b.outline[1], i);
        labels.segment(p[0], p[1], q[0], q[1], 1.2 * u, false);
      } else if (m >= 3) {
        for (let k = 0; k < m; ++k) {
          const p = xy(b.outline[k], i), q = xy(b.outline[(k + 1) % m], i);
          labels.segment(p[0], p[1], q[0], q[1], 0.6 * u, false);
        }
      }
    });
    if (actuator) {
      const p = xy(data.driver.from, i), q = xy(data.driver.joint, i), m = [(p[0] + q[0]) / 2, (p[1] + q[1]) / 2];
      labels.segment(p[0], p[1], m[0], m[1], 1.75 * u, false);
      labels.segment(m[0], m[1], q[0], q[1], 0.6 * u, false);
    }
    sliders.forEach(function (s) { const p = xy(s.slider.joint, i); labels.disc(p[0], p[1], 4.7 * u); });
    joints.forEach(function (joint, j) {
      const p = xy(j, i);
      labels.disc(p[0], p[1], jointRadius);
      if (joint.ground) labels.box(p[0], p[1] + 3.5 * u, 5 * u, 3.5 * u);  // the pivot's triangle and hatching
      const vx = arrows[j] ? vxs[j][i] : null, vy = arrows[j] ? vys[j][i] : null;
      if (vx !== null && vy !== null && Math.hypot(vx, vy) > 0) {
        labels.segment(p[0], p[1], p[0] + vx * arrowScale, p[1] - vy * arrowScale, 0.7 * u, true);
      }
      let dx = 0, dy = 0;
      neighbours[j].forEach(function (k) {
        const q = xy(k, i), l = Math.hypot(q[0] - p[0], q[1] - p[1]);
        if (l > 0) { dx += (q[0] - p[0]) / l; dy += (q[1] - p[1]) / l; }
      });
      dx = -dx; dy = -dy;  // away from them
      if (joint.ground) { dx = dx >= 0 ? 1 : -1; dy = -0.7; }
      const n = Math.hypot(dx, dy);
      if (n < 1e-9) { dx = 0; dy = -1; } else { dx /= n; dy /= n; }
      labels.ax[j] = p[0]; labels.ay[j] = p[1]; labels.px[j] = dx; labels.py[j] = dy;
    });
    for (let k = 0; forcesOn && k < forceEnds.length; k += 4) {
      if (forceEnds[k] === forceEnds[k]) labels.segment(forceEnds[k], forceEnds[k + 1], forceEnds[k + 2], forceEnds[k + 3], 0.8 * u, true);
    }
    labels.place();
    names.forEach(function (t, j) {
      t.setAttribute('x', labels.cx[j] - nameBoxes[j].ox);
      t.setAttribute('y', labels.cy[j] - nameBoxes[j].oy);
    });
  }

  // 8. Wiring: the slider, the buttons, Play (requestAnimationFrame, real time), printing.
  slider.addEventListener('input', function () { show(Number(slider.value)); position = shown; });
  first.addEventListener('click', function () { show(0); });
  last.addEventListener('click', function () { show(count - 1); });
  previous.addEventListener('click', function () { show(shown - 1); });
  next.addEventListener('click', function () { show(shown + 1); });
  let playing = false, position = 0, then = 0;
  function frame(now) {
    if (!playing) return;
    if (then) position += (now - then) / 1000 * rate;
    then = now;
    if (position >= count) position -= count * Math.floor(position / count);
    if ((position | 0) !== shown) show(position | 0);
    requestAnimationFrame(frame);
  }
  play.addEventListener('click', function () {
    playing = !playing;
    play.textContent = playing ? 'Pause' : 'Play';
    play.setAttribute('aria-pressed', String(playing));
    position = shown;
    then = 0;
    if (playing) requestAnimationFrame(frame);
  });
  // The arrow keys, Home and End anywhere on the page that is not a control of its own (the slider
  // takes them itself), as on the lab reports' steppers.
  document.addEventListener('keydown', function (event) {
    const tag = event.target && event.target.tagName;
    if (event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey || /^(INPUT|SELECT|TEXTAREA|BUTTON)$/.test(tag)) return;
    const to = {ArrowLeft: shown - 1, ArrowRight: shown + 1, Home: 0, End: count - 1}[event.key];
    if (to === undefined) return;
    event.preventDefault();
    show(to);
    position = shown;
  });
  const details = document.getElementById('pose-details');
  if (details && count > 30) details.open = false;
  window.addEventListener('beforeprint', function () { if (details) details.open = true; });

  // The first pose shown: the best-conditioned (smallest kappa(J)), as --svg draws; never a pose
  // collapsed at a limit.
  let start = firstOk;
  if (cols.condition) {
    for (let i = 0; i < count; ++i) {
      if (ok[i] && cols.condition[i] !== null && (cols.condition[start] === null || cols.condition[i] < cols.condition[start])) start = i;
    }
  }
  show(start);
  // For tests and the curious: the pose shown, and a way to show another.
  window.numlabLinkage = {data: data, shown: function () { return shown; }, show: show};
})();
