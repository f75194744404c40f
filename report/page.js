// ncsim run report: builds the page from the embedded JSON (report/html.cpp) with uPlot.
// Sets #ncsim-status data-state="ready" once every chart has drawn with > 0 points, "error"
// on any script error, console.error or empty chart (the headless test reads it).
(function () {
  'use strict';
  var D = JSON.parse(document.getElementById('ncsim-data').textContent);
  var root = document.getElementById('report');
  var status = document.getElementById('ncsim-status');
  var expected = 0, drawn = 0, empty = [], building = true;
  var COLORS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#8c564b', '#e377c2',
                '#17becf', '#7f7f7f', '#bcbd22'];
  var W = Math.max(640, Math.min(1200, (root.clientWidth || 1000) - 10));

  function update() {
    var errors = window.__ncsimErrors.length;
    status.dataset.charts = String(expected);
    status.dataset.drawn = String(drawn);
    status.dataset.empty = String(empty.length);
    status.dataset.errors = String(errors);
    if (errors > 0 || empty.length > 0) {
      status.dataset.state = 'error';
      status.textContent = 'page error: ' + window.__ncsimErrors.concat(
          empty.map(function (n) { return 'empty chart ' + n; })).join('; ');
    } else if (!building && drawn === expected) {
      status.dataset.state = 'ready';
      // Time from navigation start to the last chart drawn [ms] (docs/benchmarks.md).
      status.dataset.ms = String(Math.round(performance.now()));
      status.textContent = expected + ' charts drawn in ' + status.dataset.ms + ' ms';
    }
  }

  function el(tag, parent, text, cls) {
    var e = document.createElement(tag);
    if (text !== undefined && text !== null) e.textContent = text;
    if (cls) e.className = cls;
    if (parent) parent.appendChild(e);
    return e;
  }

  function fmt(v, digits) {
    if (v === null || v === undefined) return '\u2013';
    return String(Number(Number(v).toPrecision(digits || 6)));
  }

  function table(parent, head, rows, leftCols) {
    var t = el('table', parent);
    var tr = el('tr', t);
    head.forEach(function (h, i) { el('th', tr, h, leftCols && leftCols.indexOf(i) >= 0 ? 'l' : ''); });
    rows.forEach(function (r) {
      var row = el('tr', t);
      r.forEach(function (c, i) { el('td', row, c, leftCols && leftCols.indexOf(i) >= 0 ? 'l' : ''); });
    });
    return t;
  }

  // Counts the chart once its first draw is done; a chart without a finite point is "empty".
  function drawHook(name, points) {
    var done = false;
    return function () {
      if (done) return;
      done = true;
      if (points > 0) drawn++; else empty.push(name);
      update();
    };
  }

  function finiteCount(arr) {
    var n = 0;
    for (var i = 0; i < arr.length; i++) if (arr[i] !== null && isFinite(arr[i])) n++;
    return n;
  }

  function constant(v) {
    var a = new Array(D.t.length);
    for (var i = 0; i < a.length; i++) a[i] = v;
    return a;
  }

  // A chart over time: defs = [{label, data, color, dash}].
  function timeChart(parent, title, unit, defs) {
    if (D.t.length === 0) return null;  // no cycle: the header says so, no empty chart
    var data = [D.t];
    var series = [{label: 't [s]'}];
    var points = 0;
    defs.forEach(function (d) {
      data.push(d.data);
      points += finiteCount(d.data);
      series.push({label: d.label, stroke: d.color, width: d.dash ? 1 : 1.5, dash: d.dash,
                   points: {show: false}});
    });
    expected++;
    var box = el('div', parent);
    return new uPlot({
      title: title, width: W, height: 230,
      scales: {x: {time: false}},
      axes: [{label: 't [s]'}, {label: unit, size: 70}],
      series: series,
      hooks: {draw: [drawHook(title, points)]},
    }, data, box);
  }

  // A toolpath view: coordinates a and b of the thinned path, equal scales.
  function pathChart(parent, title, pts, a, b) {
    var dims = D.path.dims, xs = [], ys = [];
    if (pts.length < dims) return null;
    for (var i = 0; i + dims - 1 < pts.length; i += dims) {
      xs.push(pts[i + a]);
      ys.push(b < dims ? pts[i + b] : 0);
    }
    var lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (var k = 0; k < xs.length; k++) {
      lo[0] = Math.min(lo[0], xs[k]); hi[0] = Math.max(hi[0], xs[k]);
      lo[1] = Math.min(lo[1], ys[k]); hi[1] = Math.max(hi[1], ys[k]);
    }
    var span = Math.max(hi[0] - lo[0], hi[1] - lo[1], 1e-3) * 1.08;
    var cx = (lo[0] + hi[0]) / 2, cy = (lo[1] + hi[1]) / 2;
    var na = D.axes[a], nb = b < D.axes.length ? D.axes[b] : '-';
    expected++;
    var box = el('div', parent);
    return new uPlot({
      mode: 2, title: title, width: 480, height: 480,
      legend: {show: false},
      cursor: {show: false, drag: {x: false, y: false}},
      scales: {
        x: {time: false, range: function () { return [cx - span / 2, cx + span / 2]; }},
        y: {range: function () { return [cy - span / 2, cy + span / 2]; }},
      },
      axes: [{label: na + ' [mm]'}, {label: nb + ' [mm]', size: 70}],
      series: [{}, {label: title, stroke: COLORS[0], width: 1.5, points: {show: false},
                    paths: uPlot.paths.linear()}],
      hooks: {draw: [drawHook(title, xs.length)]},
    }, [null, [xs, ys]], box);
  }

  function series(i) { return D.s[i]; }

  // --- Header and outcome.
  el('h1', root, 'ncsim run report: ' + D.program);
  var info = el('p', root);
  info.textContent = 'machine ' + D.machine + ', cycle ' + fmt(D.cycle_s * 1e3) + ' ms, ' +
      D.total.cycles + ' cycles, ' + fmt(D.total.total_s) + ' s, path ' +
      fmt(D.total.distance_mm) + ' mm; ' + D.blocks + ' blocks';
  var outcome = el('p', root);
  el('span', outcome, 'outcome: ');
  el('span', outcome, D.outcome, D.outcome === 'ok' ? 'ok' : 'bad');
  if (D.stop) el('p', root, 'stop reason: ' + D.stop);
  if (D.error) el('pre', root, D.error, 'err');
  if (D.t.length === 0) el('p', root, 'The run has no interpolation cycle: nothing to chart.', 'bad');
  var sp = D.total.split;
  table(root, ['rapid [s]', 'feed [s]', 'dwell [s]', 'exact stop [s]', 'waiting [s]', 'held [s]'],
        [[fmt(sp.rapid), fmt(sp.feed), fmt(sp.dwell), fmt(sp.exact_stop), fmt(sp.waiting),
          fmt(sp.held)]]);

  // --- Audit.
  el('h2', root, 'Audit');
  var A = D.audit;
  var verdict = el('p', root);
  el('span', verdict, 'verdict: ');
  el('span', verdict, A.ok ? 'ok' : A.violation_count + ' violations', A.ok ? 'ok' : 'bad');
  el('span', verdict, ' \u2013 contour deviation ' + fmt(A.contour_mm) + ' mm (tolerance ' +
     fmt(A.contour_tolerance_mm) + ' mm), ' + A.steps + ' documented steps within their ' +
     'formulas, ' + A.cycles + ' cycles');
  table(root, ['axis', 'max |v|', 'v limit', 'max |a|', 'a limit', 'max |j|', 'j limit'],
        A.axes.map(function (x, i) {
          return [D.axes[i], fmt(x.v), fmt(x.v_limit), fmt(x.a), fmt(x.a_limit), fmt(x.j),
                  fmt(x.j_limit)];
        }), [0]);
  if (A.violations.length > 0) {
    el('h3', root, 'Violations' + (A.violation_count > A.violations.length ?
        ' (first ' + A.violations.length + ' of ' + A.violation_count + ')' : ''));
    table(root, ['t [s]', 'line', 'axis', 'quantity', 'method', 'value', 'limit'],
          A.violations.map(function (v) {
            return [fmt(v.t, 9), v.line, v.axis, v.quantity, v.method, fmt(v.value), fmt(v.limit)];
          }), [2, 3, 4]);
  }

  // --- Toolpath.
  el('h2', root, 'Toolpath (MCS)');
  el('p', root, D.path.mcs.length / D.path.dims + ' points, thinned to ' + fmt(D.path.tol_mm) +
     ' mm', 'note');
  var row = el('div', root, null, 'row');
  if (D.path.dims >= 2) {
    pathChart(row, 'MCS ' + D.axes[0] + D.axes[1], D.path.mcs, 0, 1);
    if (D.path.dims >= 3) pathChart(row, 'MCS ' + D.axes[0] + D.axes[2], D.path.mcs, 0, 2);
  }
  if (D.path.pcs1.length > 0) {
    el('h2', root, 'Toolpath (PCS1, on the conveyor)');
    var row2 = el('div', root, null, 'row');
    pathChart(row2, 'PCS1 ' + D.axes[0] + D.axes[1], D.path.pcs1, 0, 1);
    if (D.path.dims >= 3) pathChart(row2, 'PCS1 ' + D.axes[0] + D.axes[2], D.path.pcs1, 0, 2);
  }

  // --- Path velocity.
  var n = D.axes.length;
  el('h2', root, 'Path velocity');
  el('p', root, 'decimated: min and max of every ' + D.bucket_cycles + ' cycles', 'note');
  timeChart(root, 'path velocity against programmed feed', 'mm/s', [
    {label: 'v_path', data: series(5 * n), color: COLORS[0]},
    {label: 'feed (programmed)', data: series(5 * n + 1), color: COLORS[1], dash: [6, 4]},
  ]);

  // --- Axes.
  D.axes.forEach(function (name, i) {
    var L = A.axes[i];
    el('h2', root, 'Axis ' + name);
    var pos = [{label: name, data: series(5 * i), color: COLORS[0]}];
    var soft = D.soft_limits[i] || [null, null];
    if (soft[0] !== null) pos.push({label: 'min (P-AXIS-00177)', data: constant(soft[0]), color: COLORS[1], dash: [6, 4]});
    if (soft[1] !== null) pos.push({label: 'max (P-AXIS-00178)', data: constant(soft[1]), color: COLORS[1], dash: [6, 4]});
    timeChart(root, name + ' position', 'mm', pos);
    [['velocity', 'mm/s', 1, L.v_limit, ''], ['acceleration', 'mm/s^2', 2, L.a_limit, ''],
     ['jerk', 'mm/s^3', 3, L.j_limit, ' (limit holds on jerk-limited slopes; STEP is not)']
    ].forEach(function (q) {
      timeChart(root, name + ' ' + q[0] + q[4], q[1], [
        {label: name + ' ' + q[0], data: series(5 * i + q[2]), color: COLORS[0]},
        {label: '+limit', data: constant(q[3]), color: COLORS[1], dash: [6, 4]},
        {label: '-limit', data: constant(-q[3]), color: COLORS[1], dash: [6, 4]},
      ]);
    });
    timeChart(root, name + ' following error', 'mm',
              [{label: name + '.ferr', data: series(5 * i + 4), color: COLORS[2]}]);
  });

  // --- Conveyor (named series, when the run has them).
  if (D.named.length > 0) {
    el('h2', root, 'Conveyor');
    D.named.forEach(function (s, k) {
      timeChart(root, s.name, s.unit, [{label: s.name, data: series(5 * n + 2 + k), color: COLORS[k % 10]}]);
    });
  }

  // --- Blocks.
  el('h2', root, 'Slowest blocks');
  el('p', root, 'the ' + D.slowest.length + ' longest of ' + D.blocks +
     ' block records (ncsim time --blocks), longest first', 'note');
  table(root, ['line', 'time [s]', 'distance [mm]', 'feed programmed [mm/min]',
               'feed reached [mm/min]', 'rapid [s]', 'feed [s]', 'dwell [s]', 'exact stop [s]',
               'waiting [s]'],
        D.slowest.map(function (b) {
          return [b.line, fmt(b.time_s), fmt(b.distance_mm), fmt(b.feed_programmed_mm_min),
                  fmt(b.feed_reached_mm_min), fmt(b.split.rapid), fmt(b.split.feed),
                  fmt(b.split.dwell), fmt(b.split.exact_stop), fmt(b.split.waiting)];
        }));
  building = false;
  update();
})();
