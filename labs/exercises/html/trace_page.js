// trace.html (labs/exercises/trace_page.cpp): steps through the student's trace and numlab's
// together. The page works without this script (the static table); with it, one step at a time is
// shown side by side, and the parting step says how the two traces part.
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("trace-data").textContent);
  var steps = Math.max(data.yours.length, data.numlab.length);
  var names = { pivot_row: "pivot row", residual_inf: "||f||_inf", step_inf: "||dx||_inf" };
  var element = function (id) { return document.getElementById(id); };
  var stepper = element("stepper"), slider = element("slider"), table = element("trace-table");
  var current = -1;

  // 1. A small DOM helper: make(tag, attributes, children...).
  function make(tag, attributes) {
    var node = document.createElement(tag);
    Object.keys(attributes || {}).forEach(function (key) {
      if (key === "text") node.textContent = attributes[key];
      else node.setAttribute(key, attributes[key]);
    });
    for (var i = 2; i < arguments.length; i++) if (arguments[i]) node.appendChild(arguments[i]);
    return node;
  }

  function shown(value) {
    if (value === null || value === undefined) return "\u2014";
    return String(value);
  }

  // 2. The values of one step: each field (a list field entry by entry), yours beside numlab's.
  function values(k) {
    var yours = data.yours[k] || null, numlab = data.numlab[k] || null;
    var caption = "Step " + (k + 1) + ": yours beside numlab's";
    var body = make("tbody");
    data.fields.forEach(function (field) {
      var a = yours ? yours[field] : undefined, b = numlab ? numlab[field] : undefined;
      var list = Array.isArray(a) || Array.isArray(b);
      var count = list ? Math.max(Array.isArray(a) ? a.length : 0, Array.isArray(b) ? b.length : 0) : 1;
      for (var i = 0; i < count; i++) {
        var label = list ? field + "[" + i + "]" : names[field] || field;
        var mine = list ? (Array.isArray(a) ? a[i] : undefined) : a;
        var theirs = list ? (Array.isArray(b) ? b[i] : undefined) : b;
        var parts = k === data.parting && field === data.parting_field && (!list || data.parting_entry === i);
        var row = make("tr", parts ? { "class": "differs-row" } : {},
          make("th", { scope: "row", text: label }),
          make("td", { "class": parts ? "differs" : "", text: shown(mine) }),
          make("td", { text: shown(theirs) }));
        body.appendChild(row);
      }
    });
    return make("table", { id: "step-table" }, make("caption", { text: caption }),
      make("thead", {}, make("tr", {}, make("th", { scope: "col", text: "" }), make("th", { scope: "col", text: "yours" }),
        make("th", { scope: "col", text: "numlab's" }))), body);
  }

  // 3. What numlab chose from at this step (GEPP: the column's entries on and below the diagonal).
  function context(k) {
    var here = data.context && data.context[k];
    if (!here || !here.candidates) return null;
    var numlabRow = data.numlab[k] ? data.numlab[k].pivot_row : null;
    var yourRow = k <= data.parting && data.yours[k] ? data.yours[k].pivot_row : null;
    // numlab's multiplier for each other row: l_i = a_ik / pivot (the row keeps it wherever the swap puts it)
    var pivot = data.numlab[k] ? data.numlab[k].pivot : null;
    var body = make("tbody");
    here.candidates.forEach(function (a, j) {
      var i = here.first_row + j, marks = [];
      if (i === numlabRow) marks.push("numlab's pivot");
      if (i === yourRow) marks.push("your pivot");
      var cls = i === numlabRow ? "chosen-numlab" : i === yourRow ? "chosen-yours" : "";
      var multiplier = i === numlabRow || pivot === null ? "\u2014" : String(a / pivot);
      body.appendChild(make("tr", { id: "candidate-" + i },
        make("th", { scope: "row", text: "row " + i }), make("td", { "class": cls, text: String(a) }),
        make("td", { "class": cls, text: String(Math.abs(a)) }), make("td", { "class": "multiplier", text: multiplier }),
        make("td", { text: marks.join(", ") })));
    });
    var caption = "numlab's column " + (k + data.first_number) + " before the swap: a_ik for i = " + here.first_row +
      " and below" + (k > data.parting ? " (numlab's matrix: yours differs after step " + (data.parting + 1) + ")" : "");
    return make("table", { id: "candidates" }, make("caption", { text: caption }),
      make("thead", {}, make("tr", {}, make("th", { scope: "col", text: "row" }), make("th", { scope: "col", text: "a_ik" }),
        make("th", { scope: "col", text: "|a_ik|" }), make("th", { scope: "col", text: "numlab's l = a_ik / pivot" }),
        make("th", { scope: "col", text: "" }))), body);
  }

  // 3b. Newton's ||f|| or Gauss-Seidel's update per step, both traces on a log scale, drawn up to
  // step k (the axes fixed by every step, so the curves grow as one steps on).
  var plotted = data.fields.indexOf("residual_inf") >= 0 ? "residual_inf" : data.fields.indexOf("update_inf") >= 0 ? "update_inf" : null;
  var SVG = "http://www.w3.org/2000/svg";
  function series(steps_) {
    return steps_.map(function (step) { return step && typeof step[plotted] === "number" && step[plotted] > 0 ? step[plotted] : null; });
  }
  function plot(k) {
    if (!plotted) return null;
    var both = [series(data.yours), series(data.numlab)];
    var logs = [];
    both.forEach(function (values) { values.forEach(function (v) { if (v !== null) logs.push(Math.log10(v)); }); });
    if (logs.length === 0) return null;
    var low = Math.floor(Math.min.apply(null, logs)), high = Math.max(Math.ceil(Math.max.apply(null, logs)), low + 1);
    var width = 460, height = 200, left = 56, right = 12, top = 22, bottom = 30;
    var x = function (i) { return left + (steps > 1 ? i / (steps - 1) : 0.5) * (width - left - right); };
    var y = function (v) { return top + (high - v) / (high - low) * (height - top - bottom); };
    var svg = document.createElementNS(SVG, "svg");
    svg.setAttribute("viewBox", "0 0 " + width + " " + height);
    svg.setAttribute("id", "trace-plot");
    svg.setAttribute("role", "img");
    var title = (names[plotted] || plotted) + " per " + data.step_name + ", log scale, steps 1 to " + (k + 1);
    svg.setAttribute("aria-label", title + ": yours and numlab's");
    function add(tag, attributes, text) {
      var node = document.createElementNS(SVG, tag);
      Object.keys(attributes).forEach(function (key) { node.setAttribute(key, attributes[key]); });
      if (text !== undefined) node.textContent = text;
      svg.appendChild(node);
      return node;
    }
    add("text", { x: left, y: 14, "class": "plot-title" }, title);
    var every = Math.max(1, Math.ceil((high - low) / 6));
    for (var e = low; e <= high; e += every) {
      add("line", { x1: left, x2: width - right, y1: y(e), y2: y(e), "class": "plot-grid" });
      add("text", { x: left - 4, y: y(e) + 4, "class": "plot-tick" }, "1e" + e);
    }
    add("line", { x1: x(data.parting), x2: x(data.parting), y1: top, y2: height - bottom, "class": "plot-parting" });
    var late = x(data.parting) > width * 0.6;  // the label on the side of the line with room for it
    add("text", { x: x(data.parting) + (late ? -3 : 3), y: height - bottom - 4, "class": "plot-tick" + (late ? " plot-right" : " plot-left") },
      "they part");
    [["yours", both[0]], ["numlab", both[1]]].forEach(function (pair) {
      var points = [];
      for (var i = 0; i <= k && i < pair[1].length; i++) if (pair[1][i] !== null) points.push(x(i) + "," + y(Math.log10(pair[1][i])));
      add("polyline", { points: points.join(" "), "class": "plot-" + pair[0], "data-points": String(points.length) });
    });
    add("text", { x: width - right, y: 14, "class": "plot-tick plot-yours" }, "yours —");
    add("text", { x: width - right, y: 28, "class": "plot-tick plot-numlab" }, "numlab's —");
    return svg;
  }

  function replace(id, node) {
    var box = element(id);
    while (box.firstChild) box.removeChild(box.firstChild);
    if (node) box.appendChild(node);
  }

  // 4. Show step k (0-based): the controls, the sentence, the values, the table's row.
  function go(k) {
    k = Math.max(0, Math.min(steps - 1, k));
    if (k === current) return;
    current = k;
    slider.value = String(k + 1);
    element("first").disabled = element("previous").disabled = k === 0;
    element("last").disabled = element("next").disabled = k === steps - 1;
    var where = k < data.parting ? "the same as numlab's" : k === data.parting ? "where the traces part" : "after they parted";
    element("position").textContent = "Step " + (k + 1) + " of " + steps + " (" + data.step_name + " " +
      (k + data.first_number) + "): " + where;
    var sentence = element("step-sentence");
    sentence.className = "sentence" + (k === data.parting ? " parts" : "");
    sentence.textContent = k === data.parting ? data.sentence
      : k < data.parting ? "Your " + data.step_name + " agrees with numlab's here."
      : "The traces parted at step " + (data.parting + 1) + ": from there each follows its own earlier steps.";
    replace("step-values", values(k));
    replace("step-context", context(k) || plot(k));
    var old = table.querySelector("tr.current");
    if (old) { old.classList.remove("current"); old.removeAttribute("aria-current"); }
    var row = element("step-" + (k + 1));
    if (row) {
      row.classList.add("current");
      row.setAttribute("aria-current", "step");
      table.scrollTop = Math.max(0, row.offsetTop - table.clientHeight / 2);
    }
    stepper.setAttribute("data-step", String(k + 1));
  }

  // 5. The controls: buttons, the slider, and the keys (the slider keeps its own arrow keys).
  element("first").addEventListener("click", function () { go(0); });
  element("previous").addEventListener("click", function () { go(current - 1); });
  element("next").addEventListener("click", function () { go(current + 1); });
  element("last").addEventListener("click", function () { go(steps - 1); });
  element("to-parting").addEventListener("click", function () { go(data.parting); });
  slider.addEventListener("input", function () { go(Number(slider.value) - 1); });
  document.addEventListener("keydown", function (event) {
    if (event.altKey || event.ctrlKey || event.metaKey || event.target === slider) return;
    var tag = event.target && event.target.tagName;
    if (tag === "INPUT" || tag === "TEXTAREA" || tag === "SELECT") return;
    var moves = { ArrowLeft: current - 1, ArrowRight: current + 1, Home: 0, End: steps - 1 };
    if (!(event.key in moves)) return;
    event.preventDefault();
    go(moves[event.key]);
  });

  // 6. Start: the stepper shown, the table scrolls inside itself, at step N of #step-N or step 1.
  stepper.hidden = false;
  table.classList.add("stepping");
  var hash = /^#step-(\d+)$/.exec(window.location.hash);
  go(hash ? Number(hash[1]) - 1 : 0);
}());
