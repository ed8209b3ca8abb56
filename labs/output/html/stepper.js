// numlab's lab-report steppers. Each <div class="stepper" data-kind="gepp|sweeps|newton"> holds one
// traced solve as JSON: "trace", the records `--trace --format json` prints, and "lines", the text
// `--trace` prints for each. This script adds the controls (first, previous, play, next, last, a
// slider, the arrow keys) and draws the current step. Without it the page still shows the static
// trace printed just above each stepper.
(function () {
  'use strict';
  const SVG = 'http://www.w3.org/2000/svg';
  const reducedMotion = window.matchMedia && window.matchMedia('(prefers-reduced-motion: reduce)').matches;

  // 1. Small helpers: elements, numbers, a readout line.
  function el(tag, attrs, text) {
    const node = document.createElement(tag);
    for (const [key, value] of Object.entries(attrs || {})) node.setAttribute(key, value);
    if (text !== undefined) node.textContent = text;
    return node;
  }
  // As C's %.4e prints it (two exponent digits at least), so a readout reads as in the printed line.
  const sci = (v) => (v === null || v === undefined ? '-' : Number(v).toExponential(4).replace(/e([+-])(\d)$/, 'e$10$2'));
  const num = (v) => (v === null || v === undefined ? '-' : String(Number(Number(v).toPrecision(6))));
  function readout(view, label, role, value) {
    const row = el('div', { class: 'stepper-readout' });
    row.append(el('span', { class: 'stepper-label' }, label + ' '), el('span', { 'data-role': role }, value));
    view.append(row);
  }

  // 2. A log-scale plot of `values` (all steps fix the axes), drawn up to step `upto`.
  function plot(values, upto, title) {
    const width = 420, height = 170, left = 52, bottom = 28, top = 18;
    const logs = values.map((v) => Math.log10(Math.max(Math.abs(v), 1e-300)));
    const low = Math.floor(Math.min(...logs)), high = Math.max(Math.ceil(Math.max(...logs)), low + 1);
    const x = (k) => left + (values.length > 1 ? (k / (values.length - 1)) : 0.5) * (width - left - 10);
    const y = (v) => top + (high - v) / (high - low) * (height - top - bottom);
    const svg = document.createElementNS(SVG, 'svg');
    svg.setAttribute('viewBox', `0 0 ${width} ${height}`);
    svg.setAttribute('class', 'stepper-plot');
    svg.setAttribute('role', 'img');
    svg.setAttribute('aria-label', `${title}, log scale, steps 1 to ${upto + 1} of ${values.length}`);
    const add = (tag, attrs, text) => {
      const node = document.createElementNS(SVG, tag);
      for (const [key, value] of Object.entries(attrs)) node.setAttribute(key, value);
      if (text !== undefined) node.textContent = text;
      svg.append(node);
    };
    add('text', { x: left, y: 12, class: 'stepper-plot-title' }, title);
    const every = Math.max(1, Math.ceil((high - low) / 6));
    for (let e = high; e >= low; e -= every) {  // from the top, so the highest decade is labelled
      add('line', { x1: left, x2: width - 10, y1: y(e), y2: y(e), class: 'stepper-grid' });
      add('text', { x: left - 4, y: y(e) + 4, class: 'stepper-tick' }, `1e${e}`);
    }
    add('text', { x: (left + width) / 2, y: height - 6, class: 'stepper-axis' }, 'step');
    add('text', { x: x(0), y: height - bottom + 12, class: 'stepper-axis' }, '1');
    add('text', { x: x(values.length - 1), y: height - bottom + 12, class: 'stepper-axis' }, String(values.length));
    const points = logs.slice(0, upto + 1).map((v, k) => `${x(k)},${y(v)}`).join(' ');
    add('polyline', { points, class: 'stepper-curve' });
    add('circle', { cx: x(upto), cy: y(logs[upto]), r: 4, class: 'stepper-now' });
    return svg;
  }

  // 3. A matrix as a table: `rows` of numbers, the last column the right-hand side (unless mark.noRhs).
  function matrixTable(rows, mark) {
    const table = el('table', { class: 'stepper-matrix' });
    rows.forEach((row, i) => {
      const tr = el('tr', { class: mark.rows.includes(i) ? 'touched' : '' });
      row.forEach((value, j) => {
        const td = el('td', {}, num(value));
        if (j === row.length - 1 && !mark.noRhs) td.classList.add('rhs');
        if (i === mark.pivot && j === mark.pivot) td.classList.add('pivot');
        tr.append(td);
      });
      if (mark.multipliers) tr.append(el('td', { class: 'multiplier' }, mark.multipliers[i] === undefined ? '' : `l = ${num(mark.multipliers[i])}`));
      table.append(tr);
    });
    return table;
  }

  // 4. What each kind of trace draws for its record k.
  const views = {
    // Gaussian elimination: the augmented matrix after each swap and elimination, then back substitution.
    gepp(data, k, view) {
      const record = data.trace[k];
      const column = record.column;  // 1-based, as printed
      let before = data.start, after = data.start;
      for (let i = 0; i <= k; i += 1) {
        if (!data.trace[i].augmented) continue;
        if (i < k) before = data.trace[i].augmented;
        after = data.trace[i].augmented;
      }
      // Growth so far: max |a_ij| over the current matrix's upper triangle (the active block included)
      // over max |a_ij| of A; at the last step it is the growth factor numlab reports.
      const scale = data.start ? Math.max(...data.start.flatMap((row) => row.slice(0, -1).map(Math.abs))) : NaN;
      let largest = 0;
      if (after) after.forEach((row, r) => row.slice(r, -1).forEach((v) => { largest = Math.max(largest, Math.abs(v)); }));
      readout(view, 'event', 'event', record.event.replace(/_/g, ' '));
      readout(view, 'column', 'column', String(column));
      const mark = { rows: [], pivot: -1 };
      if (record.event === 'row_swap') {
        readout(view, 'pivot row (found)', 'pivot-row', String(record.swapped_with_row));
        readout(view, 'pivot', 'pivot', num(record.pivot));
        mark.rows = [column - 1, record.swapped_with_row - 1];
        mark.pivot = column - 1;
      } else if (record.event === 'elimination') {
        readout(view, 'pivot row', 'pivot-row', String(column));
        readout(view, 'pivot', 'pivot', num(record.pivot));
        mark.pivot = column - 1;
        mark.multipliers = {};
        for (let i = column; i < before.length; i += 1) {
          mark.rows.push(i);
          mark.multipliers[i] = before[i][column - 1] / record.pivot;
        }
      } else {
        readout(view, `x${column}`, 'value', num(record.value));
        mark.rows = [column - 1];
        const x = data.trace.slice(0, k + 1).filter((r) => r.event === 'back_substitution')
          .map((r) => `x${r.column} = ${num(r.value)}`);
        readout(view, 'solved so far', 'x', x.join(', '));
      }
      if (after && data.start) readout(view, 'growth factor so far', 'growth', num(largest / scale));
      if (after) view.append(matrixTable(after, mark));
      else view.append(el('p', {}, 'The matrix is too large to show (more than 12 rows).'));
    },

    // The 2x2 closed form: det A judged by kappa_2, then A^-1 = adj(A) / det A, then x = A^-1 b.
    'closed-form'(data, k, view) {
      const record = data.trace[k];
      const start = data.trace[0];
      readout(view, 'event', 'event', record.event);
      readout(view, 'det A', 'det', num(start.determinant));
      readout(view, 'kappa_2(A)', 'kappa', num(start.condition_number));
      if (record.event === 'determinant') view.append(matrixTable(record.augmented, { rows: [], pivot: -1 }));
      if (record.event === 'inverse') view.append(matrixTable(record.inverse, { rows: [0, 1], pivot: -1, noRhs: true }));
      if (record.event === 'solution') readout(view, 'x', 'x', record.x.map(num).join('  '));
    },

    // Gauss-Seidel: one record per sweep, the residual history drawn as it grows.
    sweeps(data, k, view) {
      const record = data.trace[k];
      readout(view, 'sweep', 'sweep', String(record.sweep));
      if (record.x) readout(view, 'iterate x', 'x', record.x.map(num).join('  '));
      readout(view, '||dx||_inf', 'step', sci(record.step_inf));
      readout(view, '||b - A x||_inf', 'residual', sci(record.residual_inf));
      view.append(plot(data.trace.map((r) => r.residual_inf), k, '||b - A x||_inf per sweep'));
    },

    // Newton (full or sequential): one record per iteration, the convergence plot up to it.
    newton(data, k, view) {
      const record = data.trace[k];
      if (record.block !== undefined) {
        const order = [...new Set(data.trace.map((r) => r.block))];
        const chips = el('div', { class: 'stepper-blocks', 'aria-label': 'block order' });
        order.forEach((b) => chips.append(el('span', { class: b === record.block ? 'block current' : 'block' }, `block ${b}`)));
        view.append(chips);
        readout(view, 'block', 'block', String(record.block));
      }
      readout(view, 'iteration k', 'iteration', String(record.iteration));
      readout(view, '||f||_inf', 'fnorm', sci(record.residual_inf));
      readout(view, '||f||_2', 'fnorm2', sci(record.residual_2));
      readout(view, '||dx||_inf', 'step', sci(record.step_inf));
      readout(view, 'linear solve', 'status', record.linear_status || '-');
      readout(view, 'inner iterations', 'inner', record.linear_iterations === undefined ? '-' : String(record.linear_iterations));
      readout(view, 'lambda', 'lambda', num(record.damping) + (record.damping < 1 ? ' (damped)' : ''));
      view.append(plot(data.trace.map((r) => r.residual_inf), k, '||f||_inf per iteration'));
    },
  };

  // 5. One stepper: the controls, the printed line and the view of the current step.
  function makeStepper(root) {
    const data = JSON.parse(root.querySelector('script[type="application/json"]').textContent);
    const draw = views[root.dataset.kind];
    const count = data.trace.length;
    if (!draw || count === 0) return;
    const name = root.dataset.caption || 'the trace';
    const bar = el('div', { class: 'stepper-controls', role: 'group', 'aria-label': `Step through ${name}` });
    const button = (role, label, text) => {
      const b = el('button', { type: 'button', 'data-action': role, 'aria-label': label }, text);
      bar.append(b);
      return b;
    };
    const first = button('first', 'First step', '|\u25C0'), previous = button('previous', 'Previous step', '\u25C0');
    const play = button('play', 'Play', '\u25B6\uFE0E play'), next = button('next', 'Next step', '\u25B6');
    const last = button('last', 'Last step', '\u25B6|');
    const slider = el('input', { type: 'range', min: '0', max: String(count - 1), value: '0', 'aria-label': 'Step' });
    const position = el('span', { class: 'stepper-position', 'data-role': 'position', 'aria-live': 'polite' });
    bar.append(slider, position);
    const header = el('pre', { class: 'stepper-header', 'data-role': 'header' }, (data.header || '').replace(/\n$/, ''));
    const line = el('pre', { class: 'stepper-line', 'data-role': 'line' });
    const view = el('div', { class: 'stepper-view' });
    root.append(bar, header, line, view);
    if (!data.header) header.hidden = true;
    root.tabIndex = 0;

    let current = 0, timer = null;
    function show(k) {
      current = Math.max(0, Math.min(count - 1, k));
      slider.value = String(current);
      slider.setAttribute('aria-valuetext', `step ${current + 1} of ${count}`);
      position.textContent = `step ${current + 1} of ${count}`;
      line.textContent = data.lines[current];
      view.replaceChildren();
      draw(data, current, view);
      first.disabled = previous.disabled = current === 0;
      next.disabled = last.disabled = current === count - 1;
      root.dataset.step = String(current);
    }
    function stop() {
      if (timer !== null) clearInterval(timer);
      timer = null;
      play.textContent = '\u25B6\uFE0E play';
      play.setAttribute('aria-label', 'Play');
    }
    function start() {
      if (current === count - 1) show(0);
      play.textContent = '\u275A\u275A pause';
      play.setAttribute('aria-label', 'Pause');
      timer = setInterval(() => { if (current >= count - 1) stop(); else show(current + 1); }, reducedMotion ? 1200 : 700);
    }
    first.addEventListener('click', () => { stop(); show(0); });
    previous.addEventListener('click', () => { stop(); show(current - 1); });
    next.addEventListener('click', () => { stop(); show(current + 1); });
    last.addEventListener('click', () => { stop(); show(count - 1); });
    play.addEventListener('click', () => (timer === null ? start() : stop()));
    slider.addEventListener('input', () => { stop(); show(Number(slider.value)); });
    root.addEventListener('keydown', (event) => {
      if (event.target === slider) return;  // the slider moves itself with the arrow keys
      const moves = { ArrowLeft: current - 1, ArrowRight: current + 1, Home: 0, End: count - 1 };
      if (!(event.key in moves)) return;
      event.preventDefault();
      stop();
      show(moves[event.key]);
    });
    root.classList.add('stepper-ready');
    show(0);
  }

  document.querySelectorAll('.stepper').forEach(makeStepper);
})();
