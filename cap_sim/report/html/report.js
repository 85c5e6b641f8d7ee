// The HTML report's script (docs/report.md). The page's essentials are plain
// HTML; this adds the player, the heat maps' hover, the sortable table, the
// timeline, the charts and the save buttons, all from the data the page
// carries: the --report JSON (#report-data), the --trace JSON (#trace-data)
// and each frame's windows and packed completion cycles (#page-data).
// Every part records the figures it was built from in data-* attributes.
// The page's address may hold settings after '#': t (the player's time in
// simulated seconds), frame, and sort (a column key, '-' first for descending).
(function () {
  'use strict';

  const byId = (id) => document.getElementById(id);
  // The data blocks escape "</" and the comment opener (html_report.cpp); the
  // saved files are the original text. ('\x3c' is '<', so that this file holds no
  // comment opener.)
  const unescapeBlock = (text) => text.replace(/\\u003c!--/g, '\x3c!--').replace(/<\\\//g, '</');
  const report = JSON.parse(byId('report-data').textContent);
  const page = JSON.parse(byId('page-data').textContent);
  const hz = report.clock_hz;
  const [gridRows, gridCols] = report.cells_grid.split('x').map(Number);
  const params = new URLSearchParams(location.hash.slice(1));

  document.documentElement.classList.add('scripted');

  // ---- small helpers ----
  const group = (n) => Math.round(n).toLocaleString('en-US');
  const seconds = (cycles, digits = 3) => (cycles / hz).toFixed(digits) + ' s';
  const clamp = (v, lo, hi) => Math.min(hi, Math.max(lo, v));
  const escapeHtml = (s) => String(s).replace(/[&<>"']/g, (c) => '&#' + c.charCodeAt(0) + ';');
  const cellName = (id) => 'cell[' + Math.floor(id / gridCols) + ',' + (id % gridCols) + ']';

  const kViridis = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
  function viridis(t) {
    t = clamp(Number.isFinite(t) ? t : 0.5, 0, 1) * 4;
    const i = Math.min(Math.floor(t), 3), f = t - i;
    const c = kViridis[i].map((v, k) => Math.round(v + f * (kViridis[i + 1][k] - v)));
    return 'rgb(' + c.join(',') + ')';
  }

  const tip = document.createElement('div');
  tip.className = 'tip';
  document.body.appendChild(tip);
  function showTip(text, event) {
    tip.textContent = text;
    tip.style.display = 'block';
    const x = event.clientX + 14, y = event.clientY + 14;
    const w = tip.offsetWidth, h = tip.offsetHeight;
    tip.style.left = (x + w > innerWidth ? event.clientX - w - 10 : x) + 'px';
    tip.style.top = (y + h > innerHeight ? event.clientY - h - 10 : y) + 'px';
  }
  const hideTip = () => { tip.style.display = 'none'; };

  // Runs fn once the image has its pixels.
  function whenLoaded(img, fn) {
    if (img.complete && img.naturalWidth > 0) fn();
    else img.addEventListener('load', fn, { once: true });
  }

  // Listeners of the player's time (the timeline draws it as a cursor), and
  // the time it shows.
  const timeListeners = [];
  let playerTime = null;

  // ---- completion cycles ----
  // Unpacks a frame's completion cycles (pack_completion_cycles): per window
  // in order (a cell's; on demand a tile's, traced by window_cells[tile]), per
  // pixel in video-memory order, the cycles since the window's previous pixel
  // as unsigned LEB128, zig-zag coded when the frame is `signed` (stealing,
  // where chunk k of a window was traced by chunk_cells[window][k]). Numbers
  // stay exact up to 2^53.
  function decodeFrame(f) {
    const frame = page.frames[f];
    if (frame.decoded) return frame.decoded;
    const width = report.width, n = report.width * report.height;
    const bytes = atob(frame.completion);
    const done = new Float64Array(n), owner = new Int32Array(n).fill(-1), home = new Int32Array(n).fill(-1);
    let pos = 0, first = Infinity, last = 0;
    frame.windows.forEach(([ox, oy, columns, rows, sx, sy], window) => {
      const cell = frame.window_cells ? frame.window_cells[window] : window;
      let t = 0, k = 0;
      for (let r = 0; r < rows; r++) {
        let s = (oy + r * sy) * width + ox;
        for (let c = 0; c < columns; c++, s += sx, k++) {
          let v = 0, scale = 1, b;
          do {
            b = bytes.charCodeAt(pos++);
            v += (b & 127) * scale;
            scale *= 128;
          } while (b & 128);
          t += frame.signed ? (v % 2 === 0 ? v / 2 : -(v + 1) / 2) : v;
          done[s] = t;
          owner[s] = frame.chunk_cells ? frame.chunk_cells[window][Math.floor(k / frame.chunk_pixels)] : cell;
          home[s] = cell;
          if (t < first) first = t;
          if (t > last) last = t;
        }
      }
    });
    if (pos !== bytes.length) throw new Error('the completion data does not match the windows');
    frame.decoded = { done, owner, home, first, last };
    return frame.decoded;
  }

  function pixelText(f, x, y) {
    const d = decodeFrame(f);
    const s = y * report.width + x;
    return 'pixel (' + x + ', ' + y + ') of ' + cellName(d.owner[s]) + '\non the screen at ' +
      seconds(d.done[s], 6) + '\ncycle ' + group(d.done[s]);
  }

  // The screen pixel under the mouse on an element showing the screen.
  function pixelAt(element, event) {
    const box = element.getBoundingClientRect();
    const x = Math.floor((event.clientX - box.left) / box.width * report.width);
    const y = Math.floor((event.clientY - box.top) / box.height * report.height);
    return x >= 0 && y >= 0 && x < report.width && y < report.height ? [x, y] : null;
  }

  function hoverPixels(element, frameOf) {
    element.addEventListener('mousemove', (e) => {
      const p = pixelAt(element, e);
      if (p) showTip(pixelText(frameOf(), p[0], p[1]), e);
      else hideTip();
    });
    element.addEventListener('mouseleave', hideTip);
  }

  // ---- the player ----
  function buildPlayer() {
    const host = byId('player');
    const frames = page.frames.length;
    const width = report.width, height = report.height, n = width * height;
    const firstScreen = byId('screen-0');
    let frame = clamp(parseInt(params.get('frame') || '0', 10) || 0, 0, frames - 1);
    host.innerHTML =
      '<div class="player-controls"><button type="button" class="play">Play</button>' +
      '<input type="range" min="0" max="1000" step="1" value="1000" aria-label="simulated time">' +
      '<span class="time"></span>' +
      (frames > 1 ? '<label>frame <select class="frame"></select></label>' : '') + '</div>' +
      '<canvas class="player-screen" width="' + width + '" height="' + height + '"></canvas>';
    const canvas = host.querySelector('canvas');
    canvas.style.width = firstScreen.style.width;
    const context = canvas.getContext('2d');
    const shown = context.createImageData(width, height);
    const button = host.querySelector('.play');
    const slider = host.querySelector('input');
    const readout = host.querySelector('.time');
    const select = host.querySelector('select');
    if (select) {
      for (let f = 0; f < frames; f++) select.add(new Option('' + f, '' + f));
      select.value = '' + frame;
    }

    let colours = null;  // the frame's finished screen, RGBA
    // Pixels not yet in video memory: dark, with a faint diagonal hatch so that
    // they stand apart from a dark background.
    const blank = new Uint8ClampedArray(4 * n);
    for (let i = 0, j = 0; i < n; i++, j += 4) {
      const v = ((i % width) + Math.floor(i / width)) % 6 === 0 ? 58 : 34;
      blank[j] = v; blank[j + 1] = v + 3; blank[j + 2] = v + 8; blank[j + 3] = 255;
    }
    let time = 0, lo = 0, hi = 0, playing = false, lastTick = 0;

    function range() {
      const d = decodeFrame(frame);
      // One frame: from the run's start to the last "done"; in a sequence, from
      // the start of the frame's distribution unit to its last pixel.
      lo = page.frames[frame].start_cycles;
      hi = frames > 1 ? d.last : report.total_cycles;
    }

    function draw() {
      const d = decodeFrame(frame);
      const out = shown.data, src = colours;
      let count = 0;
      for (let i = 0, j = 0; i < n; i++, j += 4) {
        const from = d.done[i] <= time ? src : blank;
        if (from === src) count++;
        out[j] = from[j]; out[j + 1] = from[j + 1]; out[j + 2] = from[j + 2]; out[j + 3] = 255;
      }
      context.putImageData(shown, 0, 0);
      readout.textContent = seconds(time) + ' of ' + seconds(hi) + ' \u00b7 ' + group(count) + ' of ' +
        group(n) + ' pixels on the screen';
      slider.value = hi > lo ? Math.round((time - lo) / (hi - lo) * 1000) : 1000;
      Object.assign(host.dataset, {
        frame: frame, pixels: n, timeCycles: time, shown: count,
        firstCycles: d.first, lastCycles: d.last, startCycles: lo, endCycles: hi,
      });
      playerTime = time;
      timeListeners.forEach((fn) => fn(time, frame));
    }

    function setTime(t) {
      time = clamp(Math.round(t), lo, hi);
      draw();
    }

    function loadFrame(f, t) {
      frame = f;
      range();
      // The completion map beside the player is the frame's.
      document.querySelectorAll('#completion-maps figure').forEach((fig) =>
        fig.classList.toggle('other-frame', +fig.dataset.frame !== f));
      const img = byId('screen-' + f);
      whenLoaded(img, () => {
        const scratch = document.createElement('canvas');
        scratch.width = width;
        scratch.height = height;
        const c = scratch.getContext('2d');
        c.drawImage(img, 0, 0);
        colours = c.getImageData(0, 0, width, height).data;
        setTime(t === undefined ? hi : t);
      });
    }

    function tick(now) {
      if (!playing) return;
      // The whole range in about ten seconds.
      const step = lastTick ? (now - lastTick) / 10000 * (hi - lo) : 0;
      lastTick = now;
      setTime(time + step);
      if (time >= hi) {
        playing = false;
        button.textContent = 'Play';
        return;
      }
      requestAnimationFrame(tick);
    }

    button.addEventListener('click', () => {
      playing = !playing;
      button.textContent = playing ? 'Pause' : 'Play';
      if (!playing) return;
      if (time >= hi) setTime(lo);
      lastTick = 0;
      requestAnimationFrame(tick);
    });
    slider.addEventListener('input', () => setTime(lo + (hi - lo) * slider.value / 1000));
    if (select) select.addEventListener('change', () => loadFrame(+select.value));
    hoverPixels(canvas, () => frame);

    const t = parseFloat(params.get('t'));
    loadFrame(frame, Number.isFinite(t) ? t * hz : undefined);
    // The player shows the screens now.
    byId('screens').hidden = true;
  }

  function buildCompletionHover() {
    document.querySelectorAll('img.completion-map').forEach((img) => {
      const f = +img.id.slice('completion-map-'.length);
      hoverPixels(img, () => f);
    });
  }

  // ---- the cells: heat map and table ----
  const kCellMetrics = {
    busy_cycles: 'busy', finish_cycles: 'finish', idle_cycles: 'idle', comm_cycles: 'comm',
    rays: 'rays', pixels: 'pixels',
  };

  function cellText(id) {
    const c = report.cells[id];
    let text = cellName(id) + '\n' + group(c.pixels) + ' pixels, ' + group(c.rays) + ' rays\nbusy ' +
      seconds(c.busy_cycles) + ', idle ' + seconds(c.idle_cycles) + ', comm ' + seconds(c.comm_cycles) +
      '\nfinish ' + seconds(c.finish_cycles) + ' (cycle ' + group(c.finish_cycles) + ')';
    if (c.subdivide_cycles !== undefined)
      text += '\ntrace corners ' + seconds(c.trace_corners_cycles) + ', exchange ' + seconds(c.exchange_cycles) +
        ', subdivide ' + seconds(c.subdivide_cycles);
    return text;
  }

  function buildCellMap() {
    const host = byId('cell-map');
    const size = clamp(Math.floor(440 / Math.max(gridRows, gridCols)), 6, 64);
    const w = gridCols * size, h = gridRows * size;
    host.innerHTML = '<div class="controls"><label>Heat map of <select>' +
      Object.entries(kCellMetrics).map(([k, v]) => '<option value="' + k + '">' + v + '</option>').join('') +
      '</select></label></div><div class="map"></div>';
    const select = host.querySelector('select');
    const map = host.querySelector('.map');

    function draw(metric) {
      const values = report.cells.map((c) => c[metric]);
      const lo = Math.min(...values), hi = Math.max(...values);
      const isCycles = metric.endsWith('_cycles');
      const label = (v) => isCycles ? seconds(v) : group(v);
      let rects = '';
      report.cells.forEach((c, id) => {
        const t = hi > lo ? (c[metric] - lo) / (hi - lo) : 0.5;
        rects += '<rect class="cell" x="' + c.col * size + '" y="' + c.row * size + '" width="' + size +
          '" height="' + size + '" fill="' + viridis(t) + '" stroke="#282828" stroke-width="' +
          (size > 10 ? 1 : 0) + '" data-cell="' + id + '" data-value="' + c[metric] + '"></rect>';
      });
      const stops = kViridis.map((c, i) => '<stop offset="' + i * 25 + '%" stop-color="rgb(' + c.join(',') +
        ')"></stop>').join('');
      map.innerHTML = '<svg width="' + w + '" height="' + (h + 40) + '" viewBox="0 0 ' + w + ' ' + (h + 40) +
        '"><defs><linearGradient id="cell-map-scale">' + stops + '</linearGradient></defs>' + rects +
        '<rect x="0" y="' + (h + 8) + '" width="' + w + '" height="10" fill="url(#cell-map-scale)"></rect>' +
        '<text x="0" y="' + (h + 32) + '" font-size="12">' + label(lo) + '</text><text x="' + w +
        '" y="' + (h + 32) + '" font-size="12" text-anchor="end">' + label(hi) + '</text></svg>';
      Object.assign(host.dataset, { cells: report.cells.length, metric: metric, min: lo, max: hi });
    }

    select.addEventListener('change', () => draw(select.value));
    map.addEventListener('mousemove', (e) => {
      const id = e.target.dataset ? e.target.dataset.cell : undefined;
      if (id === undefined) return hideTip();
      showTip(cellText(+id), e);
    });
    map.addEventListener('mouseleave', hideTip);
    draw('busy_cycles');
  }

  function buildTable() {
    const table = byId('cell-table');
    const heads = Array.from(table.tHead.rows[0].cells);
    const body = table.tBodies[0];
    const rows = Array.from(body.rows);
    const value = (tr, key) => key === 'cell' ? +tr.dataset.cell : report.cells[+tr.dataset.cell][key];
    // Each row carries its exact figures from the report, which the sort uses
    // (the table shows rounded seconds).
    rows.forEach((tr) => {
      const c = report.cells[+tr.dataset.cell];
      heads.forEach((th) => {
        const key = th.dataset.key;
        if (key !== 'cell') tr.setAttribute('data-' + key.replace(/_/g, '-'), c[key]);
      });
      tr.addEventListener('mousemove', (e) => showTip(cellText(+tr.dataset.cell), e));
      tr.addEventListener('mouseleave', hideTip);
    });

    function sortBy(key, descending) {
      const sorted = rows.slice().sort((a, b) =>
        (value(a, key) - value(b, key)) * (descending ? -1 : 1) || (+a.dataset.cell - +b.dataset.cell));
      sorted.forEach((tr) => body.appendChild(tr));
      heads.forEach((th) => th.setAttribute('aria-sort', th.dataset.key === key ?
        (descending ? 'descending' : 'ascending') : 'none'));
      table.dataset.sortKey = key;
      table.dataset.sortOrder = descending ? 'descending' : 'ascending';
      table.dataset.order = sorted.map((tr) => tr.dataset.cell).join(' ');
    }

    heads.forEach((th) => {
      th.classList.add('sortable');
      th.title = 'Sort by this column';
      th.addEventListener('click', () => {
        const again = table.dataset.sortKey === th.dataset.key;
        sortBy(th.dataset.key, again ? table.dataset.sortOrder === 'ascending' : th.dataset.key !== 'cell' &&
          th.dataset.key !== 'row' && th.dataset.key !== 'col');
      });
    });
    table.dataset.rows = rows.length;
    const wanted = params.get('sort') || 'cell';
    const key = wanted.replace(/^-/, '');
    sortBy(heads.some((th) => th.dataset.key === key) ? key : 'cell', wanted.startsWith('-'));
  }

  // ---- the timeline ----
  const kCategoryColours = {
    compute: '#4e79a7', subdivide: '#9cbbe0', broadcast: '#f28e2b', receive: '#76b7b2', message: '#e15759',
    wait: '#c9ced6', link: '#59a14f',
  };
  // By the span's category, as the trace writes it (kernel/timeline.h). Antialiased,
  // a cell's subdivision (phase 3) follows its corner tracing (phase 1) with no
  // gap: its own category, a lighter shade, tells them apart.
  const spanColour = (s) => kCategoryColours[s.cat] || '#888';

  // A round step (1, 2 or 5 times a power of ten) that puts a tick every
  // hundred pixels or so.
  function niceStep(span, pixels) {
    const raw = span / Math.max(1, pixels / 110);
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    return [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw);
  }

  function buildTimeline() {
    const host = byId('timeline');
    const trace = JSON.parse(byId('trace-data').textContent);
    const names = [];
    const tracks = [];
    let spanCount = 0, end = 0;
    for (const e of trace.traceEvents) {
      if (e.ph === 'M' && e.name === 'thread_name') names[e.tid] = e.args.name;
      if (e.ph !== 'X') continue;
      (tracks[e.tid] = tracks[e.tid] || []).push({
        begin: e.args.begin_cycles, end: e.args.end_cycles, name: e.name, cat: e.cat, bytes: e.args.bytes || 0,
      });
      spanCount++;
      end = Math.max(end, e.args.end_cycles);
    }
    const trackCount = names.length;
    for (let t = 0; t < trackCount; t++) (tracks[t] = tracks[t] || []).sort((a, b) => a.begin - b.begin);

    // The cells' and links' rows fill about 600 pixels (the box scrolls
    // beyond), the canvas staying within what browsers draw; the host's and
    // the bus's rows are always tall enough to be labelled.
    const many = (name) => name.startsWith('cell[') || name.startsWith('link ');
    const manyCount = names.filter(many).length;
    let rowHeight = clamp(Math.floor(600 / Math.max(1, manyCount)), 3, 18);
    if (manyCount * rowHeight > 12000) rowHeight = Math.max(1, Math.floor(12000 / manyCount));
    const labelled = rowHeight >= 9;
    const gutter = labelled ? 150 : 70;
    const axis = 24;
    const rowTop = [], rowSize = [];
    let height = axis;
    names.forEach((name, t) => {
      rowTop[t] = height;
      rowSize[t] = many(name) ? rowHeight : Math.max(rowHeight, 14);
      height += rowSize[t];
    });
    // With rows too thin to label, each group of them is labelled at its first.
    const groupStarts = [];
    names.forEach((name, t) => {
      if (!labelled && many(name) && (t === 0 || names[t - 1].slice(0, 4) !== name.slice(0, 4)))
        groupStarts.push([t, name.startsWith('cell[') ? 'cells' : 'links']);
    });
    const trackAt = (y) => {
      let t = 0;
      while (t < trackCount && rowTop[t] + rowSize[t] <= y) t++;
      return y < axis ? -1 : t;
    };
    host.innerHTML = '<div class="toolbar"><button type="button" data-zoom="in">Zoom in</button> ' +
      '<button type="button" data-zoom="out">Zoom out</button> <button type="button" data-zoom="all">All</button>' +
      ' <span class="view"></span></div><div class="scroll"><canvas></canvas></div><div class="keys">' +
      Object.entries(kCategoryColours).filter(([k]) => k !== 'subdivide' || report.antialiasing)
        .map(([k, c]) => '<span style="background:' + c + '"></span>' + k).join('') + '</div>';
    const canvas = host.querySelector('canvas');
    const viewText = host.querySelector('.view');
    const context = canvas.getContext('2d');
    let a = 0, b = Math.max(1, end), cursor = playerTime, width = 0;

    function layout() {
      width = Math.max(400, host.clientWidth || 1000);
      const ratio = window.devicePixelRatio || 1;
      canvas.width = Math.round(width * ratio);
      canvas.height = Math.round(height * ratio);
      canvas.style.width = width + 'px';
      canvas.style.height = height + 'px';
      context.setTransform(ratio, 0, 0, ratio, 0, 0);
    }
    const plot = () => width - gutter - 8;
    const xOf = (c) => gutter + (c - a) / (b - a) * plot();
    const cyclesAt = (x) => a + (x - gutter) / plot() * (b - a);

    function draw() {
      context.clearRect(0, 0, width, height);
      context.font = '11px system-ui, sans-serif';
      context.textBaseline = 'middle';
      for (let t = 0; t < trackCount; t++) {
        const y = rowTop[t], size = rowSize[t];
        if (t % 2) {
          context.fillStyle = '#f4f6f9';
          context.fillRect(0, y, width, size);
        }
        if (size >= 9) {
          context.fillStyle = '#38414d';
          context.fillText(names[t].length > 22 ? names[t].slice(0, 21) + '\u2026' : names[t], 4, y + size / 2);
        }
        const inner = size > 4 ? size - 2 : size;
        for (const s of tracks[t]) {
          if (s.end < a || s.begin > b) continue;
          const x0 = Math.max(gutter, xOf(s.begin)), x1 = Math.min(width - 8, xOf(s.end));
          context.fillStyle = spanColour(s);
          context.fillRect(x0, y + (size - inner) / 2, Math.max(1, x1 - x0), inner);
        }
      }
      context.fillStyle = '#38414d';
      context.textBaseline = 'top';
      groupStarts.forEach(([t, label]) => context.fillText(label, 4, rowTop[t] + 1));
      // The time axis, in simulated seconds.
      context.fillStyle = '#ffffff';
      context.fillRect(0, 0, width, axis);
      const step = niceStep((b - a) / hz, plot());  // seconds
      const digits = clamp(-Math.floor(Math.log10(step)), 0, 9);
      context.fillStyle = '#5b6573';
      context.textBaseline = 'top';
      for (let k = Math.ceil(a / hz / step); k * step * hz <= b; k++) {
        const x = xOf(k * step * hz);
        context.fillRect(x, axis - 6, 1, 6);
        context.fillText((k * step).toFixed(digits) + ' s', x + 2, 4);
      }
      if (cursor !== null && cursor >= a && cursor <= b) {
        context.fillStyle = '#e4572e';
        context.fillRect(xOf(cursor), 0, 1.5, height);
      }
      viewText.textContent = 'showing ' + seconds(a, 6) + ' to ' + seconds(b, 6);
      Object.assign(host.dataset, { viewBeginCycles: Math.round(a), viewEndCycles: Math.round(b) });
    }

    function zoom(factor, around) {
      const span = clamp((b - a) * factor, Math.min(10, end), Math.max(1, end));
      const at = around === undefined ? (a + b) / 2 : around;
      const share = (at - a) / (b - a);
      a = at - share * span;
      b = a + span;
      if (a < 0) { b -= a; a = 0; }
      if (b > end) { a -= b - end; b = end; a = Math.max(0, a); }
      draw();
    }

    host.querySelectorAll('button').forEach((btn) => btn.addEventListener('click', () => {
      if (btn.dataset.zoom === 'in') zoom(0.5);
      else if (btn.dataset.zoom === 'out') zoom(2);
      else { a = 0; b = Math.max(1, end); draw(); }
    }));
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      const box = canvas.getBoundingClientRect();
      zoom(Math.exp(e.deltaY * 0.0015), cyclesAt(e.clientX - box.left));
    }, { passive: false });
    let drag = null;
    canvas.addEventListener('mousedown', (e) => {
      drag = { x: e.clientX, a: a, b: b };
      canvas.style.cursor = 'grabbing';
    });
    window.addEventListener('mouseup', () => { drag = null; canvas.style.cursor = ''; });
    canvas.addEventListener('dblclick', () => { a = 0; b = Math.max(1, end); draw(); });
    canvas.addEventListener('mousemove', (e) => {
      const box = canvas.getBoundingClientRect();
      const x = e.clientX - box.left, y = e.clientY - box.top;
      if (drag) {
        const shift = (drag.x - e.clientX) / plot() * (drag.b - drag.a);
        const s = clamp(shift, -drag.a, end - drag.b);
        a = drag.a + s;
        b = drag.b + s;
        draw();
        return;
      }
      const t = trackAt(y);
      if (t < 0 || t >= trackCount || x < gutter) return hideTip();
      const c = cyclesAt(x), slack = (b - a) / plot() * 2;
      const span = tracks[t].find((s) => s.begin - slack <= c && c <= s.end + slack);
      if (!span) return showTip(names[t], e);
      showTip(names[t] + '\n' + span.name + '\n' + seconds(span.begin, 6) + ' to ' + seconds(span.end, 6) +
        '\ncycles ' + group(span.begin) + ' to ' + group(span.end) + ' (' + group(span.end - span.begin) + ')' +
        (span.bytes ? '\n' + group(span.bytes) + ' bytes' : ''), e);
    });
    canvas.addEventListener('mouseleave', hideTip);
    timeListeners.push((t) => { cursor = t; draw(); });
    let resizing = 0;
    window.addEventListener('resize', () => {
      clearTimeout(resizing);
      resizing = setTimeout(() => { layout(); draw(); }, 100);
    });

    Object.assign(host.dataset, { tracks: trackCount, spans: spanCount, endCycles: end });
    layout();
    draw();
  }

  function saveButton(id, dataId, fileName) {
    const button = byId(id);
    button.hidden = false;
    button.addEventListener('click', () => {
      const text = unescapeBlock(byId(dataId).textContent);
      const url = URL.createObjectURL(new Blob([text], { type: 'application/json' }));
      const link = document.createElement('a');
      link.href = url;
      link.download = fileName;
      document.body.appendChild(link);
      link.click();
      link.remove();
      setTimeout(() => URL.revokeObjectURL(url), 2000);
    });
  }

  // ---- sequences: Max, Min and d per frame ----
  function buildFrameChart() {
    const host = byId('frame-chart');
    if (!host || !report.frames) return;
    const frames = report.frames;
    const w = 760, h = 190, left = 56, right = 16, top = 26, bottom = 26;
    const x = (i) => left + (frames.length > 1 ? i / (frames.length - 1) : 0.5) * (w - left - right);
    const chart = (title, series, unit, maxValue) => {
      const y = (v) => top + (1 - v / (maxValue || 1)) * (h - top - bottom);
      let svg = '<svg width="' + w + '" height="' + h + '" viewBox="0 0 ' + w + ' ' + h + '">';
      for (let k = 0; k <= 4; k++) {
        const v = maxValue * k / 4;
        svg += '<line x1="' + left + '" x2="' + (w - right) + '" y1="' + y(v) + '" y2="' + y(v) +
          '" stroke="#e3e7ed"></line><text x="' + (left - 6) + '" y="' + (y(v) + 4) +
          '" font-size="11" text-anchor="end">' + v.toFixed(unit === '%' ? 1 : 2) + '</text>';
      }
      frames.forEach((f, i) => {
        if (frames.length <= 40 || i % Math.ceil(frames.length / 40) === 0)
          svg += '<text x="' + x(i) + '" y="' + (h - 8) + '" font-size="11" text-anchor="middle">' + i + '</text>';
      });
      for (const s of series) {
        svg += '<polyline fill="none" stroke="' + s.colour + '" stroke-width="2" points="' +
          frames.map((f, i) => x(i) + ',' + y(s.value(f))).join(' ') + '"></polyline>';
        frames.forEach((f, i) => {
          svg += '<circle cx="' + x(i) + '" cy="' + y(s.value(f)) + '" r="3" fill="' + s.colour + '"><title>frame ' +
            i + ': ' + s.name + ' ' + s.value(f).toFixed(unit === '%' ? 2 : 3) + ' ' + unit + '</title></circle>';
        });
      }
      svg += '<text x="' + left + '" y="12" font-size="12">' + escapeHtml(title) + '</text></svg>';
      return svg;
    };
    const maxSeconds = Math.max(...frames.map((f) => f.max_seconds));
    const maxD = Math.max(1, ...frames.map((f) => f.deviation_percent));
    host.innerHTML =
      chart('Max (orange) and Min (blue) per frame, seconds', [
        { name: 'Max', colour: '#f28e2b', value: (f) => f.max_seconds },
        { name: 'Min', colour: '#4e79a7', value: (f) => f.min_seconds },
      ], 's', maxSeconds) +
      chart('d per frame, percent', [{ name: 'd', colour: '#e15759', value: (f) => f.deviation_percent }], '%', maxD);
    Object.assign(host.dataset, { frames: frames.length, maxSeconds: maxSeconds });
  }

  // ---- antialiasing: the links' traffic on the grid ----
  function buildLinkMap() {
    const host = byId('link-map');
    if (!host || !report.links) return;
    const step = clamp(Math.floor(520 / Math.max(gridRows, gridCols)), 14, 80);
    const pad = step / 2;
    const w = gridCols * step + 2 * pad, h = gridRows * step + 2 * pad;
    const most = Math.max(1, ...report.links.map((l) => l.bytes));
    const busiest = Math.max(1, ...report.links.map((l) => l.busy_cycles));
    const centre = (r, c) => [pad + c * step + step / 2, pad + r * step + step / 2];
    const moves = { N: [-1, 0], E: [0, 1], S: [1, 0], W: [0, -1] };
    let svg = '<svg width="' + w + '" height="' + h + '" viewBox="0 0 ' + w + ' ' + h + '">';
    report.cells.forEach((c) => {
      const [x, y] = centre(c.row, c.col);
      const s = step * 0.28;
      svg += '<rect x="' + (x - s) + '" y="' + (y - s) + '" width="' + 2 * s + '" height="' + 2 * s +
        '" fill="#eef1f5" stroke="#9aa4b1"></rect>';
    });
    let bytes = 0;
    report.links.forEach((l) => {
      bytes += l.bytes;
      const [dr, dc] = moves[l.direction];
      const [x, y] = centre(l.row, l.col);
      // Each direction drawn to one side of the centre line, so the two
      // directions between a pair of cells stay apart.
      const off = step * 0.1;
      const ox = dr !== 0 ? dr * off : 0, oy = dc !== 0 ? -dc * off : 0;
      // A torus link that leaves the grid's edge is drawn as a stub out of it.
      const outside = l.row + dr < 0 || l.row + dr >= gridRows || l.col + dc < 0 || l.col + dc >= gridCols;
      const length = step * (outside ? 0.45 : 0.72);
      const x2 = x + dc * length + ox, y2 = y + dr * length + oy;
      const thickness = 1 + 6 * l.bytes / most;
      svg += '<line x1="' + (x + ox + dc * step * 0.28) + '" y1="' + (y + oy + dr * step * 0.28) + '" x2="' + x2 +
        '" y2="' + y2 + '" stroke="' + viridis(l.busy_cycles / busiest) + '" stroke-width="' + thickness.toFixed(2) +
        '" stroke-linecap="round"><title>cell[' + l.row + ',' + l.col + '] ' + l.direction + ': ' +
        group(l.messages) + ' messages, ' + group(l.bytes) + ' bytes, bits on the link ' + group(l.busy_cycles) +
        ' cycles, longest wait ' + group(l.max_wait_cycles) + ' cycles</title></line>';
    });
    svg += '</svg>';
    host.innerHTML = '<p class="note">Each link direction that carried corners: thicker for more bytes, ' +
      'yellower for more cycles with bits on it. Hover for its figures.</p>' + svg;
    Object.assign(host.dataset, { links: report.links.length, bytes: bytes });
  }

  // ---- maps of the screen by cell (balancing) ----
  // Neighbouring ids get distant hues (the golden angle).
  const cellColour = (id) =>
    'hsl(' + ((id * 137.508) % 360).toFixed(1) + ', 65%, ' + (42 + (id % 3) * 12) + '%)';

  // A canvas of the screen in `host`, scaled to about 512 pixels, with a
  // frame selector when the run has several frames.
  function screenMap(host, frames) {
    const w = report.width, h = report.height;
    const scale = Math.max(1, Math.floor(512 / Math.max(w, h)));
    host.innerHTML = (frames > 1 ? '<div class="controls"><label>Frame <select>' +
      Array.from({ length: frames }, (_, f) => '<option value="' + f + '">' + f + '</option>').join('') +
      '</select></label></div>' : '') + '<canvas width="' + w * scale + '" height="' + h * scale + '"></canvas>';
    const canvas = host.querySelector('canvas');
    return { scale, canvas, select: host.querySelector('select'), context: canvas.getContext('2d') };
  }

  // ---- balanced on demand: which cell traced each tile ----
  // The tiles are recomputed as balance.h cuts them: ceil(H / side) rows and
  // ceil(W / side) columns, split as block mode splits (floor(k * W / C)).
  function buildTileMap() {
    const host = byId('tile-map');
    if (!host || !report.balancing) return;
    const b = report.balancing, w = report.width, h = report.height;
    const rows = Math.ceil(h / b.tile_side), cols = Math.ceil(w / b.tile_side);
    const start = (k, length, parts) => Math.floor(k * length / parts);
    const part = (p, length, parts) => Math.floor(((p + 1) * parts - 1) / length);
    const { scale, canvas, select, context } = screenMap(host, b.tile_cells.length);
    let owners = b.tile_cells[0];

    function draw(frame) {
      owners = b.tile_cells[frame];
      owners.forEach((cell, t) => {
        const r = Math.floor(t / cols), c = t % cols;
        const x0 = start(c, w, cols), y0 = start(r, h, rows);
        context.fillStyle = cellColour(cell);
        context.fillRect(x0 * scale, y0 * scale, (start(c + 1, w, cols) - x0) * scale,
          (start(r + 1, h, rows) - y0) * scale);
      });
      Object.assign(host.dataset, { frame: frame, tiles: owners.length, cells: new Set(owners).size });
    }

    if (select) select.addEventListener('change', () => draw(+select.value));
    canvas.addEventListener('mousemove', (e) => {
      const box = canvas.getBoundingClientRect();
      const x = clamp(Math.floor((e.clientX - box.left) / box.width * w), 0, w - 1);
      const y = clamp(Math.floor((e.clientY - box.top) / box.height * h), 0, h - 1);
      const t = part(y, h, rows) * cols + part(x, w, cols);
      showTip('tile ' + t + ', traced by ' + cellName(owners[t]), e);
    });
    canvas.addEventListener('mouseleave', hideTip);
    draw(0);
  }


  // ---- stealing: which cell traced each pixel ----
  // From the page's completion data, whose chunks name their tracers
  // (decodeFrame's owner; home is the cell whose window shows the pixel).
  function buildChunkMap() {
    const host = byId('chunk-map');
    if (!host || !page.frames.length || !page.frames[0].chunk_cells) return;
    const w = report.width, h = report.height;
    const { scale, canvas, select, context } = screenMap(host, page.frames.length);
    let owner = decodeFrame(0).owner;

    function draw(frame) {
      const decoded = decodeFrame(frame);
      owner = decoded.owner;
      let stolen = 0;
      for (let s = 0; s < w * h; s++) {
        context.fillStyle = cellColour(owner[s]);
        context.fillRect((s % w) * scale, Math.floor(s / w) * scale, scale, scale);
        if (owner[s] !== decoded.home[s]) stolen++;
      }
      Object.assign(host.dataset, { frame: frame, cells: new Set(owner).size, stolen: stolen });
    }

    if (select) select.addEventListener('change', () => draw(+select.value));
    canvas.addEventListener('mousemove', (e) => {
      const box = canvas.getBoundingClientRect();
      const x = clamp(Math.floor((e.clientX - box.left) / box.width * w), 0, w - 1);
      const y = clamp(Math.floor((e.clientY - box.top) / box.height * h), 0, h - 1);
      showTip('pixel (' + x + ', ' + y + '), traced by ' + cellName(owner[y * w + x]), e);
    });
    canvas.addEventListener('mouseleave', hideTip);
    draw(0);
  }

  // plain HTML as they are.
  const parts = {
    player: buildPlayer, completion: buildCompletionHover, cellMap: buildCellMap, table: buildTable,
    timeline: buildTimeline, frameChart: buildFrameChart, linkMap: buildLinkMap, tileMap: buildTileMap,
    chunkMap: buildChunkMap,
    save: () => {
      saveButton('save-trace', 'trace-data', 'capsim-trace.json');
      saveButton('save-report', 'report-data', 'capsim-report.json');
    },
  };
  const built = [];
  for (const [name, build] of Object.entries(parts)) {
    try {
      build();
      built.push(name);
    } catch (error) {
      console.error('report: ' + name + ': ' + error);
      document.documentElement.dataset.failed = (document.documentElement.dataset.failed || '') + ' ' + name;
    }
  }
  document.documentElement.dataset.built = built.join(' ');
})();
