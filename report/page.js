// ncsim run report: builds the page from the embedded JSON (report/html.cpp) with uPlot: a run
// page (renderRun), or a line page (renderLine: the line's summary, belt, timeline and lanes,
// then renderRun per channel; report/line_page.cpp).
// Sets #ncsim-status data-state="ready" once every chart has drawn with > 0 points, "error"
// on any script error, console.error or empty chart (the headless test reads it).
(function () {
  'use strict';
  var DATA = JSON.parse(document.getElementById('ncsim-data').textContent);
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

  // The [t0, t1] intervals where the 0/1 indicator `d` is 1 in a row or the next (a decimated
  // bucket that holds it at all is covered whole).
  function intervals(t, d) {
    var iv = [];
    for (var r = 0; r < t.length; r++) {
      if (d[r] !== 1) continue;
      var t0 = r > 0 && d[r - 1] !== 1 ? t[r - 1] : t[r];
      var t1 = r + 1 < t.length ? t[r + 1] : t[r];
      if (iv.length > 0 && iv[iv.length - 1][1] >= t0) iv[iv.length - 1][1] = t1;
      else iv.push([t0, t1]);
    }
    return iv;
  }

  // A chart over the times `t`: defs = [{label, data, color, dash}]; `drawClear` hooks draw
  // behind the series (the sync phases' bands).
  function timeChartOf(t, drawClear, parent, title, unit, defs) {
    if (t.length === 0) return null;  // no cycle: the header says so, no empty chart
    var data = [t];
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
      hooks: {draw: [drawHook(title, points)], drawClear: drawClear},
    }, data, box);
  }

  // --- One run's sections (a run page, or one channel of a line page `depth` headings down);
  // returns what the status marks count.
  function renderRun(D, root, depth) {
  var h1 = 'h' + (1 + depth), h2 = 'h' + (2 + depth), h3 = 'h' + (3 + depth);
  function constant(v) {
    var a = new Array(D.t.length);
    for (var i = 0; i < a.length; i++) a[i] = v;
    return a;
  }

  // --- Named series by name (docs/report.md "Data contract"); the conveyor's sync phases are
  // 0/1 indicators drawn as shaded bands behind every time chart.
  var nAxes = D.axes.length;
  function named(name) {
    for (var k = 0; k < D.named.length; k++)
      if (D.named[k].name === name) return D.s[5 * nAxes + 2 + k];
    return null;
  }
  var PHASES = [['phase.waiting', 'waiting for the measured value', 'rgba(255,170,0,0.16)'],
                ['phase.catch_up', 'catch-up', 'rgba(214,39,40,0.13)'],
                ['phase.synchronised', 'synchronised', 'rgba(44,160,44,0.13)'],
                ['phase.leaving', 'leaving (after #SYNC OUT)', 'rgba(148,103,189,0.15)']];
  // Per phase the [t0, t1] intervals where its indicator is 1 in a row or the next (a
  // decimated bucket that holds the phase at all is shaded whole).
  var bands = [];
  PHASES.forEach(function (p) {
    var d = named(p[0]);
    if (!d) return;
    bands.push({label: p[1], color: p[2], iv: intervals(D.t, d)});
  });
  var bandCount = 0;
  bands.forEach(function (b) { bandCount += b.iv.length; });
  function drawBands(u) {
    var ctx = u.ctx, top = u.bbox.top, h = u.bbox.height;
    ctx.save();
    bands.forEach(function (b) {
      ctx.fillStyle = b.color;
      b.iv.forEach(function (iv) {
        var x0 = u.valToPos(iv[0], 'x', true), x1 = u.valToPos(iv[1], 'x', true);
        ctx.fillRect(x0, top, Math.max(1, x1 - x0), h);
      });
    });
    ctx.restore();
  }
  function bandLegend(parent) {
    if (bandCount === 0) return;
    var p = el('p', parent, 'sync phases (shaded on every time chart): ', 'note');
    bands.forEach(function (b) {
      var sw = el('span', p, '\u00a0\u00a0\u00a0\u00a0', 'swatch');
      sw.style.background = b.color.replace(/[0-9.]+\)$/, '0.5)');
      el('span', p, ' ' + b.label + ' (' + b.iv.length + ')  ');
    });
  }

  // A chart over time: defs = [{label, data, color, dash}].
  function timeChart(parent, title, unit, defs) {
    return timeChartOf(D.t, bandCount > 0 ? [drawBands] : [], parent, title, unit, defs);
  }

  // A toolpath view: coordinates a and b of the thinned path, equal scales. `extras`:
  // outlines drawn with it ({label, color, dash, xs, ys}; xs/ys null: filled in across the
  // view), included in the view where they are near the path (below).
  function pathChart(parent, title, pts, a, b, extras) {
    var dims = D.path.dims, xs = [], ys = [];
    extras = extras || [];
    if (pts.length < dims) return null;
    for (var i = 0; i + dims - 1 < pts.length; i += dims) {
      xs.push(pts[i + a]);
      ys.push(b < dims ? pts[i + b] : 0);
    }
    var lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    function grow(x, y) {
      if (x !== null) { lo[0] = Math.min(lo[0], x); hi[0] = Math.max(hi[0], x); }
      if (y !== null) { lo[1] = Math.min(lo[1], y); hi[1] = Math.max(hi[1], y); }
    }
    for (var k = 0; k < xs.length; k++) grow(xs[k], ys[k]);
    // The view fits the path; an outline is context: its coordinates widen the view only
    // where they lie within half the path's span of it (a workspace of metres around a path of
    // centimetres would make the path a speck). Outlines beyond are clipped at the view.
    var near = Math.max(hi[0] - lo[0], hi[1] - lo[1], 1e-3) * 0.5;
    var box0 = [lo[0] - near, hi[0] + near, lo[1] - near, hi[1] + near];
    extras.forEach(function (e) {
      for (var q = 0; q < e.xs.length; q++) {
        var x = e.xs[q], y = e.ys[q];
        grow(x !== null && x >= box0[0] && x <= box0[1] ? x : null,
             y !== null && y >= box0[2] && y <= box0[3] ? y : null);
      }
    });

    var span = Math.max(hi[0] - lo[0], hi[1] - lo[1], 1e-3) * 1.08;
    var cx = (lo[0] + hi[0]) / 2, cy = (lo[1] + hi[1]) / 2;
    extras.forEach(function (e) {  // a line across the view: x or y open
      for (var q = 0; q < e.xs.length; q++) {
        if (e.xs[q] === null) e.xs[q] = cx + (q === 0 ? -span : span) / 2;
        if (e.ys[q] === null) e.ys[q] = cy + (q === 0 ? -span : span) / 2;
      }
    });
    var na = D.axes[a], nb = b < D.axes.length ? D.axes[b] : '-';
    expected++;
    var box = el('div', parent);
    var u = new uPlot({
      mode: 2, title: title, width: 480, height: 480,
      legend: {show: false},
      cursor: {show: false, drag: {x: false, y: false}},
      scales: {
        x: {time: false, range: function () { return [cx - span / 2, cx + span / 2]; }},
        y: {range: function () { return [cy - span / 2, cy + span / 2]; }},
      },
      axes: [{label: na + ' [mm]'}, {label: nb + ' [mm]', size: 70}],
      series: [{}, {label: title, stroke: COLORS[0], width: 1.5, points: {show: false},
                    paths: uPlot.paths.linear()}].concat(extras.map(function (e) {
        return {label: e.label, stroke: e.color, width: 1, dash: e.dash, points: {show: false},
                paths: uPlot.paths.linear()};
      })),
      hooks: {draw: [drawHook(title, xs.length)]},
    }, [null, [xs, ys]].concat(extras.map(function (e) { return [e.xs, e.ys]; })), box);
    // uPlot's line builder decimates at >= 4 points per pixel assuming x sorted, which would
    // draw a toolpath wrong (docs/report.md "Decimation"): an error, never a silent one.
    if (xs.length - 1 >= 4 * u.bbox.width)
      console.error('toolpath ' + title + ': ' + xs.length + ' points for ' +
                    Math.round(u.bbox.width) + ' px');
    return u;
  }

  // The conveyor workspace (seed 004 §2.1.3, §4.4) on the view of MCS coordinates a, b: the
  // cuboid's rectangle and the pos_limit line (P-CHAN-00374, an MCS X position); on the PCS1
  // view only the faces that stand still against the workpiece (`sides`: those parallel to
  // a belt along MCS X), as lines across the view.
  function workspaceOutlines(a, b, sides) {
    var w = D.workspace;
    if (!w || b >= 3 || a >= 3) return [];
    var L = w.lower, U = w.upper, out = [];
    if (!sides) {
      out.push({label: 'workspace', color: COLORS[4], dash: [8, 4],
                xs: [L[a], U[a], U[a], L[a], L[a]], ys: [L[b], L[b], U[b], U[b], L[b]]});
      if (a === 0) out.push({label: 'pos_limit (P-CHAN-00374)', color: COLORS[1], dash: [3, 3],
                             xs: [w.pos_limit, w.pos_limit], ys: [L[b], U[b]]});
    } else if (w.along_x && a === 0) {
      out.push({label: 'workspace face', color: COLORS[4], dash: [8, 4], xs: [null, null],
                ys: [L[b], L[b]]});
      out.push({label: 'workspace face', color: COLORS[4], dash: [8, 4], xs: [null, null],
                ys: [U[b], U[b]]});
    }
    return out;
  }

  function series(i) { return D.s[i]; }

  // --- Header and outcome.
  if (depth === 0) el(h1, root, 'ncsim run report: ' + D.program);
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
  table(root, ['rapid [s]', 'feed [s]', 'dwell [s]', 'tech [s]', 'exact stop [s]', 'waiting [s]',
               'held [s]'],
        [[fmt(sp.rapid), fmt(sp.feed), fmt(sp.dwell), fmt(sp.tech), fmt(sp.exact_stop),
          fmt(sp.waiting), fmt(sp.held)]]);

  // --- Audit.
  el(h2, root, 'Audit');
  var A = D.audit;
  var verdict = el('p', root);
  el('span', verdict, 'verdict: ');
  el('span', verdict, A.ok ? 'ok' : A.violation_count + ' violations', A.ok ? 'ok' : 'bad');
  el('span', verdict, ' \u2013 contour deviation ' + fmt(A.contour_mm) + ' mm (tolerance ' +
     fmt(A.contour_tolerance_mm) + ' mm), ' + A.steps + ' documented steps within their ' +
     'formulas, ' + A.cycles + ' cycles');
  // No cycle on a jerk-limited slope: |j| is not limited (the CLI's audit says so too).
  function auditRow(name, x) {
    var jerk = x.jerk_cycles > 0;
    return [name, fmt(x.v), fmt(x.v_limit), fmt(x.a), fmt(x.a_limit),
            jerk ? fmt(x.j) : '\u2013', jerk ? fmt(x.j_limit) : 'not limited (STEP)'];
  }
  // Under #TRAFO ON the joints (the machine axes, deg or mm) are checked apart, as in the CLI.
  table(root, ['axis', 'max |v|', 'v limit', 'max |a|', 'a limit', 'max |j|', 'j limit'],
        A.axes.map(function (x, i) { return auditRow(D.axes[i], x); }).concat(
            A.joints.map(function (x) { return auditRow(D.axes[x.index] + ' under #TRAFO', x); })),
        [0]);
  // The documented steps apart, per kind, with the one closest to its formula (issue 12).
  if (A.step_kinds.length > 0) {
    table(root, ['documented step', 'count', 'formula', 'closest: t [s]', 'line', 'axis',
                 'step', 'bound', 'link velocity [mm/s]'],
          A.step_kinds.map(function (k) {
            return [k.kind, k.count, k.formula, fmt(k.t, 9), k.line, k.axis, fmt(k.value),
                    fmt(k.bound), fmt(k.v_link)];
          }), [0, 2, 5]);
  }
  if (A.belt_count > 0)
    el('p', root, A.belt_count + ' of the violations are the belt\u2019s own acceleration or ' +
       'jerk on top of a path within the axis\u2019s limits (004 l.454; docs/conveyor.md)', 'note');
  if (A.violations.length > 0) {
    el(h3, root, 'Violations' + (A.violation_count > A.violations.length ?
        ' (first ' + A.violations.length + ' of ' + A.violation_count + ')' : ''));
    table(root, ['t [s]', 'line', 'axis', 'quantity', 'method', 'value', 'limit'],
          A.violations.map(function (v) {
            return [fmt(v.t, 9), v.line, v.axis, v.quantity, v.method, fmt(v.value), fmt(v.limit)];
          }), [2, 3, 4]);
  }

  // --- Toolpath.
  el(h2, root, 'Toolpath (MCS)');
  el('p', root, D.path.mcs.length / D.path.dims + ' points, thinned to ' + fmt(D.path.tol_mm) +
     ' mm', 'note');
  var row = el('div', root, null, 'row');
  if (D.workspace)
    el('p', root, 'dashed: the conveyor workspace (monitored while synchronised) and, dotted, ' +
       'pos_limit P-CHAN-00374 = ' + fmt(D.workspace.pos_limit) + ' mm', 'note');
  if (D.path.dims >= 2) {
    pathChart(row, 'MCS ' + D.axes[0] + D.axes[1], D.path.mcs, 0, 1, workspaceOutlines(0, 1, false));
    if (D.path.dims >= 3)
      pathChart(row, 'MCS ' + D.axes[0] + D.axes[2], D.path.mcs, 0, 2, workspaceOutlines(0, 2, false));
  }
  if (D.path.pcs1.length > 0) {
    el(h2, root, 'Toolpath (PCS1, on the conveyor)');
    el('p', root, 'the tool on the workpiece, drawn at belt travel 0 (T0 applied)' +
       (D.workspace && D.workspace.along_x ? '; dashed: the workspace faces beside the belt, ' +
        'which stand still against the workpiece (those across the belt move with it)' : ''),
       'note');
    var row2 = el('div', root, null, 'row');
    pathChart(row2, 'PCS1 ' + D.axes[0] + D.axes[1], D.path.pcs1, 0, 1, workspaceOutlines(0, 1, true));
    if (D.path.dims >= 3)
      pathChart(row2, 'PCS1 ' + D.axes[0] + D.axes[2], D.path.pcs1, 0, 2, workspaceOutlines(0, 2, true));
  }

  // --- Path velocity.
  var n = D.axes.length;
  el(h2, root, 'Path velocity');
  el('p', root, 'decimated: min and max of every ' + D.bucket_cycles + ' cycles', 'note');
  bandLegend(root);
  timeChart(root, 'path velocity against programmed feed', 'mm/s', [
    {label: 'v_path', data: series(5 * n), color: COLORS[0]},
    {label: 'feed (programmed)', data: series(5 * n + 1), color: COLORS[1], dash: [6, 4]},
  ]);

  // --- Axes.
  D.axes.forEach(function (name, i) {
    var L = A.axes[i];
    el(h2, root, 'Axis ' + name);
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

  // --- Conveyor (named series, when the run has them): grouped charts for the known names,
  // one chart for any other; the phase indicators are the bands, not charts.
  var GROUPS = [
    ['belt velocity: real, measured (raw) and filtered (what PCS1 follows)', 'mm/s',
     [['belt_v_actual', 'real'], ['belt_v_raw', 'measured (raw)'], ['belt_v_filtered', 'filtered']]],
    ['current_pos_master (measured) and pos_master_comp (filtered + delay compensation)', 'mm',
     [['current_pos_master', 'current_pos_master'], ['pos_master_comp', 'pos_master_comp']]],
    ['synchro_lag (> 0: the machine ahead of the workpiece)', 'mm',
     [['synchro_lag', 'synchro_lag']]]];
  var grouped = {};
  var conveyorCharts = 0;
  if (D.named.length > 0) {
    el(h2, root, 'Conveyor');
    bandLegend(root);
    GROUPS.forEach(function (g) {
      var defs = [];
      g[2].forEach(function (m, j) {
        grouped[m[0]] = true;
        var d = named(m[0]);
        if (d && finiteCount(d) > 0) defs.push({label: m[1], data: d, color: COLORS[j % 10], dash: j === 0 && g[2].length > 2 ? [4, 3] : undefined});
      });
      if (defs.length > 0) {
        if (timeChart(root, g[0], g[1], defs)) conveyorCharts++;
      } else if (g[2].some(function (m) { return named(m[0]); })) {
        el('p', root, g[0] + ': no value in this run (before the first measurement, or PCS1 ' +
           'never moved)', 'note');
      }
    });
    D.named.forEach(function (s, k) {
      if (grouped[s.name] || s.unit === 'phase') return;
      if (timeChart(root, s.name, s.unit, [{label: s.name, data: series(5 * n + 2 + k), color: COLORS[k % 10]}]))
        conveyorCharts++;
    });
  }

  // --- Per workpiece (ipo::WorkpieceCycles: one row per #SYNC IN).
  // The same objects as `ncsim time --json`: {summary, rows}, times in s.
  var WP = D.workpieces;
  if (WP) {
    var S = WP.summary;
    el(h2, root, 'Per workpiece');
    el('p', root, S.workpieces + ' workpieces (' + S.complete + ' reached #SYNC OUT), ' +
       fmt(S.per_minute) + ' per minute; cycle ' + fmt(S.total_min_s) + ' .. ' +
       fmt(S.total_max_s) + ' s; lead-in before the first #SYNC IN ' + fmt(S.lead_in_s) + ' s' +
       (WP.rows.length < S.workpieces ? '; the first ' + WP.rows.length + ' rows listed' : ''),
       'note');
    var wrow = function (r, first) {
      return [first, r.workpiece || '\u2013', fmt(r.t_start_s, 9), fmt(r.waiting_s),
              fmt(r.catch_up_s), fmt(r.machining_s), fmt(r.desync_s), fmt(r.off_belt_s),
              fmt(r.total_s)];
    };
    table(root, ['#', 'workpiece', 'start [s]', 'waiting [s]', 'catch-up [s]', 'machining [s]',
                 'desync [s]', 'off belt [s]', 'total [s]'],
          WP.rows.map(function (r) { return wrow(r, r.index + (r.complete ? '' : ' (incomplete)')); })
            .concat([wrow(S, 'sum')]), [0]);
  }

  // --- Blocks.
  el(h2, root, 'Slowest blocks');
  el('p', root, 'the ' + D.slowest.length + ' longest of ' + D.blocks +
     ' block records (ncsim time --blocks), longest first', 'note');
  table(root, ['line', 'time [s]', 'distance [mm]', 'feed programmed [mm/min]',
               'feed reached [mm/min]', 'F capped by the axes to [mm/min]', 'rapid [s]',
               'feed [s]', 'dwell [s]', 'tech [s]', 'exact stop [s]', 'waiting [s]'],
        D.slowest.map(function (b) {
          return [b.line, fmt(b.time_s), fmt(b.distance_mm), fmt(b.feed_programmed_mm_min),
                  fmt(b.feed_reached_mm_min),
                  b.feed_cap_mm_min === undefined ? '' : fmt(b.feed_cap_mm_min),
                  fmt(b.split.rapid), fmt(b.split.feed),
                  fmt(b.split.dwell), fmt(b.split.tech), fmt(b.split.exact_stop),
                  fmt(b.split.waiting)];
        }));
  return {conveyor: conveyorCharts, bands: bandCount, workspace: D.workspace ? 1 : 0,
          workpieces: WP ? WP.rows.length : 0};
  }

  // --- A line page (report/line_page.cpp): L.summary is `ncsim line time --json`'s object;
  // L.t / L.s the line's decimated series: belt position, belt velocity, then per channel k
  // running (2 + 2 k) and waiting for a signal (3 + 2 k); L.runs each channel's run data.
  function renderLine(L, root) {
    var S = L.summary, W8 = S.workpieces, chans = S.channels;
    var colorOf = {};  // channel number -> its colour on the timeline and the lanes
    var LANE_COLORS = COLORS.filter(function (c, i) { return i !== 1; });  // red: missed
    chans.forEach(function (c, k) { colorOf[c.number] = LANE_COLORS[k % LANE_COLORS.length]; });
    function label(c) { return 'channel ' + c.number + (c.name === 'channel ' + c.number ? '' : ' ' + c.name); }
    el('h1', root, 'ncsim line report: ' + L.line);
    if (L.description) el('p', root, L.description, 'note');
    var failed = chans.filter(function (c) { return c.error !== undefined; });
    el('p', root, chans.length + ' channels, cycle ' + fmt(S.cycle_s * 1e3) + ' ms, end ' +
       fmt(S.end_s) + ' s' + (W8 ? '; ' + W8.taken + ' of ' + W8.arrived + ' workpieces taken, ' +
       fmt(W8.per_minute, 4) + ' per minute' : ''));
    var outcome = el('p', root);
    el('span', outcome, 'outcome: ');
    el('span', outcome, failed.length === 0 ? 'ok' : failed.length + ' channel' +
       (failed.length === 1 ? '' : 's') + ' ended with an error', failed.length === 0 ? 'ok' : 'bad');
    table(root, ['channel', 'program', 'machine', 'end [s]', 'waiting for signals [s]',
                 'utilisation [%]', 'sensor at [mm]', 'took', 'per minute', 'stop'],
          chans.map(function (c, k) {
            var R = L.runs[k];
            return [label(c), R.program, R.machine, fmt(c.end_s), fmt(c.waiting_s),
                    fmt(c.utilisation_percent), c.taken === undefined ? '' : fmt(c.sensor_at_mm),
                    c.taken === undefined ? '' : c.taken,
                    c.taken === undefined ? '' : fmt(c.per_minute, 4), c.stop];
          }), [0, 1, 2, 9]);
    failed.forEach(function (c) { el('pre', root, label(c) + ': ' + c.error, 'err'); });

    // The belt over time.
    if (L.belt) {
      el('h2', root, 'Belt');
      if (W8)
        el('p', root, W8.arrived + ' arrived, ' + W8.taken + ' taken, ' + W8.missed + ' missed, ' +
           W8.on_belt + ' on the belt at the end (' + W8.held + ' held)', 'note');
      el('p', root, 'decimated: min and max of every ' + L.bucket_cycles + ' cycles', 'note');
      timeChartOf(L.t, [], root, 'belt position (the real belt)', 'mm',
                  [{label: 'position', data: L.s[0], color: COLORS[0]}]);
      timeChartOf(L.t, [], root, 'belt velocity (the real belt)', 'mm/s',
                  [{label: 'velocity', data: L.s[1], color: COLORS[0]}]);
    }

    // Which channel took which workpiece when: each workpiece a line from its arrival at the
    // line's sensor to its fate (taken: the channel's colour and a dot; missed: red, a cross).
    var fates = W8 ? W8.fates : [];
    var timelineMarks = 0;
    var tEnd = L.t.length > 0 ? L.t[L.t.length - 1] : 0;
    fates.forEach(function (f) { tEnd = Math.max(tEnd, f.t_s === undefined ? f.arrived_s : f.t_s); });
    if (fates.length > 0) {
      el('h2', root, 'Workpieces: which channel took which, when');
      var lg = el('p', root, 'from its arrival at the line\u2019s sensor to its fate: ', 'note');
      chans.forEach(function (c) {
        if (c.taken === undefined) return;
        var sw = el('span', lg, '\u00a0\u00a0\u00a0\u00a0', 'swatch');
        sw.style.background = colorOf[c.number];
        el('span', lg, ' taken by ' + label(c) + ' (' + c.taken + ')  ');
      });
      var sm = el('span', lg, '\u00a0\u00a0\u00a0\u00a0', 'swatch');
      sm.style.background = MISSED;
      el('span', lg, ' missed (' + W8.missed + ')  ');
      if (W8.on_belt > 0) el('span', lg, ' grey: on the belt at the end (' + W8.on_belt + ')');
      timelineMarks = fates.length;
      frameChart(root, 'workpieces (arrival \u2192 taken or missed)', 'workpiece', [0, tEnd],
                 [0.5, fates[fates.length - 1].workpiece + 0.5], null, fates.length,
                 function (u) { drawFates(u, fates, colorOf); });
      var listed = fates.slice(0, 500);
      var det = el('details', root);
      el('summary', det, 'every workpiece\u2019s fate (' + fates.length + ')');
      table(det, ['workpiece', 'arrived [s]', 'fate', 'channel', 'at [s]'],
            listed.map(function (f) {
              var c = chans.filter(function (x) { return x.number === f.channel; })[0];
              return [f.workpiece, fmt(f.arrived_s, 9), f.fate, c ? label(c) : '',
                      f.t_s === undefined ? '' : fmt(f.t_s, 9)];
            }), [2, 3]);
      if (listed.length < fates.length)
        el('p', det, 'the first ' + listed.length + ' of ' + fates.length + ' listed', 'note');
    }

    // Each channel's lane: running, waiting for a signal (#WAIT / #WAIT SYN), ended.
    el('h2', root, 'Channels: running and waiting for signals');
    var lg2 = el('p', root, 'per channel, decimated like the series: ', 'note');
    [['running', 1], ['waiting for a signal', 0.35]].forEach(function (q) {
      var sw = el('span', lg2, '\u00a0\u00a0\u00a0\u00a0', 'swatch');
      sw.style.background = COLORS[0];
      sw.style.opacity = String(q[1]);
      el('span', lg2, ' ' + q[0] + '  ');
    });
    var lanes = chans.map(function (c, k) {
      return {color: colorOf[c.number], run: intervals(L.t, L.s[2 + 2 * k]),
              wait: intervals(L.t, L.s[3 + 2 * k])};
    });
    var laneCount = 0;
    lanes.forEach(function (l) { laneCount += l.run.length + l.wait.length; });
    frameChart(root, 'channel lanes', 'channel', [0, tEnd], [0, chans.length],
               chans.map(function (c, k) { return [chans.length - k - 0.5, label(c)]; }),
               laneCount, function (u) { drawLanes(u, lanes); });

    // Each channel's run report.
    var marks = {conveyor: 0, bands: 0, workspace: 0, workpieces: 0};
    L.runs.forEach(function (R, k) {
      el('h2', root, label(chans[k]) + ': ' + R.program + ' on ' + R.machine, 'channel');
      var m = renderRun(R, el('section', root), 1);
      Object.keys(marks).forEach(function (key) { marks[key] += m[key]; });
    });
    status.dataset.lineChannels = String(L.runs.length);
    status.dataset.timeline = String(timelineMarks);
    status.dataset.lanes = String(laneCount);
    return marks;
  }

  var MISSED = '#b00020';

  // A frame of axes over x range `xr` and y range `yr` drawn by `paint` (the workpieces, the
  // lanes); `ticks` [[y, text]] names the y axis's ticks (null: numbers); `marks` counts what
  // it draws (0: an empty chart).
  function frameChart(parent, title, unit, xr, yr, ticks, marks, paint) {
    expected++;
    var box = el('div', parent);
    var y = {label: unit, size: 110};
    if (ticks) {
      y.splits = function () { return ticks.map(function (t) { return t[0]; }); };
      y.values = function () { return ticks.map(function (t) { return t[1]; }); };
    }
    return new uPlot({
      title: title, width: W, height: ticks ? 60 + 40 * ticks.length : 320,
      legend: {show: false},
      scales: {x: {time: false, range: function () { return xr; }},
               y: {range: function () { return yr; }}},
      axes: [{label: 't [s]'}, y],
      series: [{label: 't [s]'}, {label: title, stroke: 'transparent', points: {show: false}}],
      hooks: {draw: [paint, drawHook(title, marks)]},
    }, [xr, [yr[0], yr[1]]], box);
  }

  function drawFates(u, fates, colorOf) {
    var ctx = u.ctx;
    ctx.save();
    ctx.lineWidth = 2;
    fates.forEach(function (f) {
      var end = f.t_s === undefined ? u.scales.x.max : f.t_s;
      var x0 = u.valToPos(f.arrived_s, 'x', true), x1 = u.valToPos(end, 'x', true);
      var y = u.valToPos(f.workpiece, 'y', true);
      var color = f.fate === 'taken' ? colorOf[f.channel] : f.fate === 'missed' ? MISSED : '#999';
      ctx.strokeStyle = color;
      ctx.setLineDash(f.fate === 'missed' ? [4, 3] : []);
      ctx.beginPath();
      ctx.moveTo(x0, y);
      ctx.lineTo(x1, y);
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = color;
      ctx.beginPath();
      if (f.fate === 'missed') {
        ctx.moveTo(x1 - 4, y - 4); ctx.lineTo(x1 + 4, y + 4);
        ctx.moveTo(x1 - 4, y + 4); ctx.lineTo(x1 + 4, y - 4);
        ctx.stroke();
      } else {
        ctx.arc(x1, y, 3.5, 0, 2 * Math.PI);
        ctx.fill();
      }
    });
    ctx.restore();
  }

  function drawLanes(u, lanes) {
    var ctx = u.ctx, n = lanes.length;
    ctx.save();
    lanes.forEach(function (l, k) {
      var top = u.valToPos(n - k - 0.1, 'y', true), bottom = u.valToPos(n - k - 0.9, 'y', true);
      [[l.run, 1], [l.wait, 0.35]].forEach(function (q) {
        ctx.fillStyle = l.color;
        ctx.globalAlpha = q[1];
        q[0].forEach(function (iv) {
          var x0 = u.valToPos(iv[0], 'x', true), x1 = u.valToPos(iv[1], 'x', true);
          ctx.fillRect(x0, top, Math.max(1, x1 - x0), bottom - top);
        });
      });
    });
    ctx.restore();
  }

  var marks = DATA.kind === 'line' ? renderLine(DATA, root) : renderRun(DATA, root, 0);
  status.dataset.conveyor = String(marks.conveyor);
  status.dataset.bands = String(marks.bands);
  status.dataset.workspace = String(marks.workspace);
  status.dataset.workpieces = String(marks.workpieces);
  building = false;
  update();
})();
