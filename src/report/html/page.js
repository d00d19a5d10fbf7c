// The pdcheck HTML report's script (embedded at build time). Reads the report
// data from #pdcheck-data; draws the summary, the findings table, the depth
// histogram and, where WebGL is available, the 3D view of the selected finding
// (three.js, inlined before this script). Nothing is fetched.
(function () {
  'use strict';

  const t0 = performance.now();
  const data = JSON.parse(document.getElementById('pdcheck-data').textContent);
  const $ = (id) => document.getElementById(id);
  // What tests and curious users can read back (state only, no behaviour).
  const api = { data: data, ready: false, selected: null, webgl: false, renders: 0, ms: {} };
  const lap = (what) => { api.ms[what] = Math.round(performance.now() - t0); };
  lap('parse');
  window.pdcheck = api;

  const STATUS_ORDER = ['interference', 'clearance_violation', 'undecided', 'error', 'false_positive', 'separated'];
  const rank = (s) => { const k = STATUS_ORDER.indexOf(s); return k < 0 ? STATUS_ORDER.length : k; };
  const units = data.units || '';
  const findings = data.findings;
  // Finding groups (findings that share a fix): "G1" for the deepest, with the member count.
  const groups = data.groups || [];
  const groupIndex = new Map(groups.map((g, n) => [g.id, n]));
  const groupLabel = (id) => (groupIndex.has(id) ? 'G' + (groupIndex.get(id) + 1) +
    ' (' + groups[groupIndex.get(id)].members.length + ')' : '');

  function el(tag, attrs, text) {
    const e = document.createElement(tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined && text !== null) e.textContent = String(text);
    return e;
  }
  function num(x, digits) {
    if (x === undefined || x === null || !isFinite(x)) return '—';
    if (x === 0) return '0';
    const a = Math.abs(x);
    return a >= 1e5 || a < 1e-3 ? x.toExponential((digits || 4) - 1) : String(+x.toPrecision(digits || 4));
  }
  function len(x) { return x === undefined || x === null ? '—' : num(x) + ' ' + units; }

  // ---- Summary ----
  function summary() {
    const s = data.summary || {};
    // The verdict first: pass, fail or incomplete (an exit-3 run is never a pass).
    const verdict = data.verdict || {};
    $('verdict').className = verdict.state || '';
    $('verdict-headline').textContent = verdict.headline || '';
    $('verdict-counts').textContent = (verdict.counts || '') + (verdict.shard ? ' · ' + verdict.shard : '');
    api.verdict = verdict.state || null;
    $('scene-line').textContent = 'Scene ' + (data.scene || '?') + ' · tolerance ' + len(data.tolerance) +
      ' · method ' + ((data.method || {}).name || '?') + ' · run time ' + num(data.seconds, 3) + ' s';
    const tool = data.tool || {};
    $('tool').textContent = (tool.name || 'pdcheck') + ' ' + (tool.version || '');
    const cards = [
      ['interference', s.interference], ['clearance_violation', s.clearance_violation],
      ['undecided', s.undecided], ['false_positive', s.false_positive], ['separated', s.separated], ['error', s.error],
      ['parts', s.parts], ['part_errors', s.part_errors], ['candidate_pairs', s.candidate_pairs],
      ['culled', s.culled], ['unchecked', s.unchecked], ['tolerance', len(data.tolerance)],
      ['units', units], ['method', (data.method || {}).name], ['run time', num(data.seconds, 3) + ' s'],
      ['exit_code', s.exit_code], ['fail_on', s.fail_on], ['failing', s.failing], ['suppressed', s.suppressed]];
    if (s.baseline)
      for (const k of ['new', 'unchanged', 'updated', 'absent', 'unknown'])
        cards.push(['baseline ' + k, s.baseline[k]]);
    const box = $('summary');
    for (const [k, v] of cards) {
      if (v === undefined || v === null) continue;
      const c = el('div', { class: 'card' });
      const value = el('div', { class: 'v' + (STATUS_ORDER.includes(k) ? ' status ' + k : '') }, v);
      c.append(value, el('div', { class: 'k' }, k.replace(/_/g, ' ')));
      box.append(c);
    }
    const notes = $('notes');
    for (const n of data.notes || []) notes.append(el('li', {}, n));
    for (const p of data.part_errors || []) notes.append(el('li', {}, 'part "' + p.id + '" unusable: ' + p.error));
  }

  // ---- Table ----
  const rows = [];      // tr per finding, same index
  let order = findings.map((_, k) => k);
  let visible = order.slice();
  let sortKey = null, sortDir = 1, current = -1;

  function buildTable() {
    const body = document.querySelector('#findings tbody');
    const statuses = new Set();
    findings.forEach((f, k) => {
      statuses.add(f.status);
      const tr = el('tr', { tabindex: '-1', 'aria-selected': 'false', 'data-k': String(k) });
      const st = el('td', { class: 'status ' + f.status }, f.status.replace(/_/g, ' '));
      if (f.suppressed) st.append(el('span', { class: 'tag', title: f.suppressed.reason || '' }, 'suppressed'));
      if (f.confirmed === false) st.append(el('span', { class: 'tag', title: 'rests on an upper bound' }, 'unconfirmed'));
      tr.append(st, el('td', { class: 'num' }, f.status === 'error' ? '—' : num(f.depth)),
        el('td', { class: 'num' }, f.status === 'error' ? '—' : num(f.margin)),
        el('td', { class: 'id', title: f.a }, f.a), el('td', { class: 'id', title: f.b }, f.b),
        el('td', {}, f.baseline_state || ''), el('td', { class: 'fp', title: f.fingerprint }, f.fingerprint.slice(0, 8) + '…'),
        el('td', { class: 'group', title: f.group || '' }, groupLabel(f.group)));
      tr.addEventListener('click', () => select(k, true, true));
      rows.push(tr);
      body.append(tr);
    });
    const sel = $('status-filter');
    [...statuses].sort((x, y) => rank(x) - rank(y)).forEach((s) => sel.append(el('option', { value: s }, s)));
    for (const th of document.querySelectorAll('#findings th')) {
      th.setAttribute('aria-sort', 'none');
      th.querySelector('button').addEventListener('click', () => sortBy(th.dataset.key, th));
    }
    for (const id of ['search', 'status-filter', 'depth-min', 'depth-max'])
      $(id).addEventListener('input', applyFilter);
    $('controls').addEventListener('submit', (e) => e.preventDefault());
    body.addEventListener('keydown', onKey);
  }

  // ---- Groups: one line each, a click lists its members ----
  function groupSentence(g) {
    const m = g.move || {};
    return g.members.length + (g.members.length === 1 ? ' finding' : ' findings') + ' · move ' + m.part + ' by ' +
      len(m.length) + ' along (' + (m.direction || []).map((x) => num(x, 3)).join(', ') + ') clears ' +
      (m.covers || []).length + ' · deepest ' + num(g.depth) + ' ' + units;
  }
  function buildGroups() {
    if (!groups.length) return;
    $('groups').hidden = false;
    const several = groups.filter((g) => g.members.length > 1).length;
    $('groups-title').textContent = 'Groups: ' + groups.length + ' (' + several + ' of several findings sharing a fix)';
    const list = $('group-list');
    groups.forEach((g, n) => {
      const b = el('button', { type: 'button', title: 'list this group\'s findings (' + g.id + ')' },
        'G' + (n + 1) + ': ' + g.parts.join(', '));
      b.addEventListener('click', () => {
        $('search').value = g.id;
        applyFilter();
        if (visible.length) select(visible[0], true, true);
      });
      const li = el('li');
      li.append(b, document.createTextNode(' ' + groupSentence(g)));
      list.append(li);
    });
  }

  function compare(key) {
    if (key === 'status') return (x, y) => rank(findings[x].status) - rank(findings[y].status) ||
      (findings[y].depth || 0) - (findings[x].depth || 0);
    if (key === 'depth' || key === 'margin') return (x, y) => {
      const u = findings[x][key], v = findings[y][key];
      return (u === undefined ? -Infinity : u) - (v === undefined ? -Infinity : v);
    };
    if (key === 'group') return (x, y) => {  // by group rank, the ungrouped last; members together
      const u = groupIndex.has(findings[x].group) ? groupIndex.get(findings[x].group) : Infinity;
      const v = groupIndex.has(findings[y].group) ? groupIndex.get(findings[y].group) : Infinity;
      return u === v ? 0 : u < v ? -1 : 1;
    };
    return (x, y) => String(findings[x][key] || '').localeCompare(String(findings[y][key] || ''));
  }

  function sortBy(key, th) {
    sortDir = sortKey === key ? -sortDir : (key === 'depth' ? -1 : 1);
    sortKey = key;
    const cmp = compare(key);
    order = findings.map((_, k) => k).sort((x, y) => sortDir * cmp(x, y) || x - y);
    for (const h of document.querySelectorAll('#findings th')) h.setAttribute('aria-sort', 'none');
    th.setAttribute('aria-sort', sortDir > 0 ? 'ascending' : 'descending');
    const body = document.querySelector('#findings tbody');
    for (const k of order) body.append(rows[k]);
    applyFilter();
  }

  function applyFilter() {
    const q = $('search').value.trim().toLowerCase();
    const status = $('status-filter').value;
    const lo = parseFloat($('depth-min').value), hi = parseFloat($('depth-max').value);
    visible = [];
    for (const k of order) {
      const f = findings[k];
      let show = (!status || f.status === status) &&
        (!q || f.a.toLowerCase().includes(q) || f.b.toLowerCase().includes(q) || f.fingerprint.includes(q) ||
          (f.group || '').startsWith(q));
      if (show && (isFinite(lo) || isFinite(hi))) {
        const d = f.depth;
        show = d !== undefined && (!isFinite(lo) || d >= lo) && (!isFinite(hi) || d <= hi);
      }
      rows[k].hidden = !show;
      if (show) visible.push(k);
    }
    $('shown').textContent = visible.length + ' of ' + findings.length + ' findings';
  }

  function onKey(e) {
    if (!visible.length) return;
    const at = visible.indexOf(current);
    let next = null;
    if (e.key === 'ArrowDown') next = visible[Math.min(visible.length - 1, at + 1)];
    else if (e.key === 'ArrowUp') next = visible[Math.max(0, at - 1)];
    else if (e.key === 'Home') next = visible[0];
    else if (e.key === 'End') next = visible[visible.length - 1];
    else if (e.key === 'Enter' || e.key === ' ') next = current;
    if (next === null || next === undefined) return;
    e.preventDefault();
    select(next, true, true);
  }

  function select(k, focus, permalink) {
    if (k < 0 || k >= findings.length) return;
    if (current >= 0) {
      rows[current].setAttribute('aria-selected', 'false');
      rows[current].tabIndex = -1;
    }
    current = k;
    const tr = rows[k];
    tr.setAttribute('aria-selected', 'true');
    tr.tabIndex = 0;
    if (focus) tr.focus({ preventScroll: true });
    tr.scrollIntoView({ block: 'nearest' });
    const f = findings[k];
    api.selected = f.fingerprint;
    const link = '#pair=' + f.fingerprint;
    $('permalink').href = link;
    if (permalink && location.hash !== link) history.replaceState(null, '', link);
    showInfo(f);
    show3d(f);
  }

  function fromHash() {
    const m = /^#pair=([0-9a-f]+)$/.exec(location.hash);
    if (!m) return false;
    const k = findings.findIndex((f) => f.fingerprint === m[1]);
    if (k < 0) return false;
    select(k, false, false);
    return true;
  }

  // ---- Details of the selected finding ----
  function showInfo(f) {
    $('view-title').textContent = f.a + ' ↔ ' + f.b;
    const info = $('view-info');
    info.textContent = '';
    const dl = el('dl');
    const add = (k, v, swatch) => {
      const dt = el('dt', {}, k);
      const dd = el('dd');
      if (swatch) dd.append(el('span', { class: 'swatch', style: 'background:' + swatch }));
      dd.append(document.createTextNode(v));
      dl.append(dt, dd);
    };
    add('status', f.status.replace(/_/g, ' ') + (f.confirmed === false ? ' (unconfirmed: an upper bound)' : ''));
    if (f.status === 'error') add('error', f.error || '');
    else {
      // The sentence is pdcheck's own (the one stderr, JUnit and SARIF give):
      // the page only adds the numbers beside it, never a claim of its own.
      if (f.text) add('finding', f.text);
      add('depth', len(f.depth) + ' (tolerance ' + len(data.tolerance) + ', margin ' + len(f.margin) + ')', COLORS.arrow);
      if (f.direction) add('direction', '(' + f.direction.map((x) => num(x, 4)).join(', ') + ')');
      add('depth source', f.depth_source || 'hull');
      if (f.depth_bounds) add('depth bounds', f.depth_bounds.map(len).join(' … '));
      if (f.exact) {
        const e = f.exact;
        const by = e.by === 'deflection-bound' ? 'certified by the deflection bound'
          : e.by === 'exact-solids' ? 'confirmed on the exact solids' : e.reason || '';
        add('exact solids', e.verdict.replace(/_/g, ' ') + (by ? ' (' + by + ')' : '') +
          (e.depth_bounds ? ', thickness ' + e.depth_bounds.map(len).join(' … ') : '') +
          (e.distance !== undefined ? ', distance ' + len(e.distance) : ''));
      }
      if (f.at) add('at', '(' + f.at.map((x) => num(x, 7)).join(', ') + '), the marked point', COLORS.at);
      if (f.group && groupIndex.has(f.group)) {
        const g = groups[groupIndex.get(f.group)];
        add('group', groupLabel(f.group) + ': ' + groupSentence(g) + ' · ' + f.group);
      }
    }
    const v = f.view;
    const how = (i) => (i === undefined || i === null ? 'no geometry' : data.meshes[i].how);
    if (v) {
      add('part A', f.a + ': ' + how(v.a), COLORS.a);
      add('part B', f.b + ': ' + how(v.b), COLORS.b);
      if (v.piece_a !== undefined) add('realising pieces', 'pieces ' + f.pieces.join(' and ') + ', outlined', COLORS.piece);
      if (v.overlap !== undefined) add('overlap', 'of ' + v.overlap_of + ': ' + how(v.overlap), COLORS.overlap);
      else if (v.overlap_note) add('overlap', 'not drawn: ' + v.overlap_note);
      if (thicknessBall(f))
        add('thickness', 'a ball of the overlap thickness (' + len(f.depth) + ') at `at`: inside both parts', COLORS.overlap);
      if (v.context && v.context.length)
        add('nearby', v.context.length + ' parts as faint boxes: ' + v.context.map((k) => data.boxes[k][0]).join(', '), '#8c959f');
    }
    if (f.baseline_state) add('baseline', f.baseline_state);
    if (f.suppressed) add('suppressed', f.suppressed.reason || '');
    for (const w of f.warnings || []) add('warning', w);
    add('fingerprint', f.fingerprint);
    info.append(dl);
  }

  // ---- 3D view ----
  const COLORS = { a: '#3b82f6', b: '#f59e0b', overlap: '#e11d48', piece: '#7c3aed', arrow: '#047857', at: '#111827' };
  let gl = null;  // { renderer, scene, camera, controls, group, boxes }
  const geometryCache = new Map(), edgeCache = new Map(), materialCache = new Map();
  function material(kind, color, opacity, make) {
    const key = kind + color + opacity;
    if (!materialCache.has(key)) materialCache.set(key, make());
    return materialCache.get(key);
  }

  function bytes(b64) {
    const s = atob(b64);
    const out = new Uint8Array(s.length);
    for (let i = 0; i < s.length; ++i) out[i] = s.charCodeAt(i);
    return out.buffer;
  }
  function geometry(i) {
    if (geometryCache.has(i)) return geometryCache.get(i);
    const m = data.meshes[i];
    const g = new THREE.BufferGeometry();
    // int16 steps of m.s (little-endian, as written), relative to m.o.
    const q = new Int16Array(bytes(m.v));
    const pos = new Float32Array(q.length);
    for (let k = 0; k < q.length; ++k) pos[k] = q[k] * m.s;
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    g.setIndex(new THREE.BufferAttribute(m.t32 ? new Uint32Array(bytes(m.t)) : new Uint16Array(bytes(m.t)), 1));
    g.computeVertexNormals();
    g.computeBoundingBox();
    geometryCache.set(i, g);
    return g;
  }

  function webglAvailable() {
    try {
      const probe = document.createElement('canvas');
      return !!(window.THREE && window.WebGLRenderingContext &&
        (probe.getContext('webgl') || probe.getContext('experimental-webgl')));
    } catch (e) {
      return false;
    }
  }

  function initGl() {
    if (!webglAvailable()) return null;
    const box = $('canvas-box');
    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xfbfcfd, 1);
    box.append(renderer.domElement);
    renderer.domElement.setAttribute('aria-label', '3D view of the selected finding');
    renderer.domElement.setAttribute('role', 'img');
    const scene = new THREE.Scene();
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    const head = new THREE.DirectionalLight(0xffffff, 0.6);
    camera.add(head);
    scene.add(camera);
    const controls = new THREE.OrbitControls(camera, renderer.domElement);
    const g = { renderer, scene, camera, controls, group: new THREE.Group(), fitBox: null, overlapBox: null };
    scene.add(g.group);
    controls.addEventListener('change', render);
    const resize = () => {
      const w = box.clientWidth || 400, h = box.clientHeight || 300;
      renderer.setSize(w, h, false);
      camera.aspect = w / h;
      camera.updateProjectionMatrix();
      render();
    };
    if (window.ResizeObserver) new ResizeObserver(resize).observe(box);
    window.addEventListener('resize', resize);
    gl = g;
    resize();
    return g;
  }

  function render() {
    if (!gl) return;
    gl.renderer.render(gl.scene, gl.camera);
    api.renders += 1;
  }

  function clearGroup() {
    for (const c of [...gl.group.children]) {
      gl.group.remove(c);
      c.traverse((o) => {
        // Materials are kept: disposing the last user of a shader costs its
        // compile again at the next selection. Per-selection geometry goes.
        if (o.geometry && !o.userData.cached) o.geometry.dispose();
      });
    }
  }

  function addMesh(i, centre, color, opacity, edges, name) {
    const m = data.meshes[i];
    const geo = geometry(i);
    const obj = new THREE.Group();
    const onTop = name === 'overlap';
    const mesh = new THREE.Mesh(geo, material('face', color, opacity, () => new THREE.MeshPhongMaterial({
      color: color, flatShading: true, transparent: opacity < 1, opacity: opacity, depthTest: !onTop,
      side: THREE.DoubleSide, depthWrite: opacity >= 1, polygonOffset: true,
      polygonOffsetFactor: 1, polygonOffsetUnits: 1 })));
    mesh.userData.cached = true;
    obj.add(mesh);
    if (edges) {
      if (!edgeCache.has(i)) edgeCache.set(i, new THREE.EdgesGeometry(geo, 25));
      const e = new THREE.LineSegments(edgeCache.get(i), material('edge', color, opacity,
        () => new THREE.LineBasicMaterial({ color: color, transparent: true, depthTest: !onTop,
          opacity: Math.min(1, opacity + 0.4) })));
      e.userData.cached = true;
      obj.add(e);
    }
    obj.position.set(m.o[0] - centre[0], m.o[1] - centre[1], m.o[2] - centre[2]);
    obj.name = name;
    obj.renderOrder = opacity < 1 ? 1 : 0;
    gl.group.add(obj);
    const b = geo.boundingBox.clone();
    b.translate(obj.position);
    return b;
  }

  // A thickness pair's depth is the diameter of a ball inside both parts at
  // `at` (docs/report-format.md): drawn as that ball, the region the solver found.
  function thicknessBall(f) {
    return f.depth_source === 'thickness' && f.at && f.depth > 0 && f.view && f.view.a !== null && f.view.b !== null;
  }

  function show3d(f) {
    const note = $('no-view');
    if (!gl) {
      note.hidden = false;
      note.textContent = 'The 3D view needs WebGL, which this browser does not offer; the table and the details work without it.';
      return;
    }
    clearGroup();
    const v = f.view;
    if (!v || (v.a === null && v.b === null) || (v.a === undefined && v.b === undefined)) {
      note.hidden = false;
      note.textContent = v ? 'No geometry for this pair (a part could not be read).' :
        'No 3D view for this finding: the page\'s geometry budget went to the findings listed first.';
      gl.renderer.domElement.style.visibility = 'hidden';
      return;
    }
    note.hidden = true;
    gl.renderer.domElement.style.visibility = 'visible';
    const has = (i) => i !== undefined && i !== null;
    const origins = [v.a, v.b].filter(has).map((i) => data.meshes[i].o);
    const centre = [0, 1, 2].map((d) => origins.reduce((s, o) => s + o[d], 0) / origins.length);
    const fit = new THREE.Box3();
    gl.partBoxes = [];
    for (const [i, name, color] of [[v.a, 'a', COLORS.a], [v.b, 'b', COLORS.b]]) {
      if (!has(i)) continue;
      const box = addMesh(i, centre, color, 0.35, true, name);
      gl.partBoxes.push(box);
      fit.union(box);
    }
    if (has(v.piece_a)) addMesh(v.piece_a, centre, COLORS.piece, 0.25, true, 'piece');
    if (has(v.piece_b)) addMesh(v.piece_b, centre, COLORS.piece, 0.25, true, 'piece');
    let arrowAt = fit.getCenter(new THREE.Vector3());
    gl.overlapBox = null;
    if (has(v.overlap)) {
      gl.overlapBox = addMesh(v.overlap, centre, COLORS.overlap, 0.85, true, 'overlap');
      // The overlap is what the row is about: drawn over the parts around it.
      gl.group.getObjectByName('overlap').traverse((o) => { o.renderOrder = 5; });
      arrowAt = gl.overlapBox.getCenter(new THREE.Vector3());
    }
    if (thicknessBall(f)) {
      const r = f.depth / 2;
      const ball = new THREE.Mesh(new THREE.SphereGeometry(r, 24, 16), material('ball', COLORS.overlap, 0.6,
        () => new THREE.MeshPhongMaterial({ color: COLORS.overlap, transparent: true, opacity: 0.6, depthTest: false })));
      ball.position.set(f.at[0] - centre[0], f.at[1] - centre[1], f.at[2] - centre[2]);
      const onTop = new THREE.Group();
      onTop.renderOrder = 6;
      onTop.name = 'thickness';
      onTop.add(ball);
      gl.group.add(onTop);
      const ballBox = new THREE.Box3().setFromCenterAndSize(ball.position, new THREE.Vector3(2 * r, 2 * r, 2 * r));
      gl.overlapBox = gl.overlapBox ? gl.overlapBox.union(ballBox) : ballBox;
    }
    const size = fit.getSize(new THREE.Vector3()).length() || 1;
    // Where the finding is (the report's `at`): a marker drawn over everything;
    // the depth arrow starts there and the first view is centred on it.
    gl.atPoint = null;
    gl.marker = null;
    gl.centre = centre;
    if (f.at) {
      gl.atPoint = new THREE.Vector3(f.at[0] - centre[0], f.at[1] - centre[1], f.at[2] - centre[2]);
      arrowAt = gl.atPoint.clone();
      const marker = new THREE.Mesh(new THREE.SphereGeometry(1, 16, 12), material('at', COLORS.at, 0.9,
        () => new THREE.MeshBasicMaterial({ color: COLORS.at, transparent: true, opacity: 0.9, depthTest: false })));
      marker.position.copy(gl.atPoint);
      // In a Group of its own: a Group's renderOrder orders it against the others
      // (the overlap's), so the marker is drawn over everything, last.
      const onTop = new THREE.Group();
      onTop.renderOrder = 11;
      onTop.name = 'at';
      onTop.add(marker);
      gl.group.add(onTop);
      gl.marker = marker;
    }
    let dir = null;
    if (f.direction && f.depth > 0) {
      dir = new THREE.Vector3(f.direction[0], f.direction[1], f.direction[2]).normalize();
      // The arrow has the depth's length, to scale; a thin line along it marks
      // the direction when the depth is too small to see at this zoom.
      const L = f.depth;
      const arrow = new THREE.ArrowHelper(dir, arrowAt, L, COLORS.arrow, 0.3 * L, 0.18 * L);
      // Drawn over everything: it usually lies inside the overlap.
      // (transparent: drawn in the pass after the translucent overlap, last).
      // A Group's renderOrder orders what is in it against other groups.
      arrow.traverse((o) => {
        if (o.material) Object.assign(o.material, { depthTest: false, transparent: true });
      });
      const onTop = new THREE.Group();
      onTop.renderOrder = 10;
      onTop.name = 'depth';
      onTop.add(arrow);
      gl.group.add(onTop);
      const guide = new THREE.BufferGeometry().setFromPoints([
        arrowAt.clone().addScaledVector(dir, -0.6 * size), arrowAt.clone().addScaledVector(dir, 0.6 * size)]);
      const line = new THREE.Line(guide, new THREE.LineDashedMaterial({
        color: COLORS.arrow, dashSize: size / 60, gapSize: size / 90 }));
      line.computeLineDistances();
      line.name = 'direction';
      gl.group.add(line);
    }
    // The rest of the assembly nearby: faint boxes (hidden with "context").
    if (v.context && v.context.length) {
      const pts = [];
      for (const k of v.context) {
        const b = data.boxes[k][1].map((x, d) => x - centre[d % 3]);
        const c = [[b[0], b[3]], [b[1], b[4]], [b[2], b[5]]];
        for (let e = 0; e < 12; ++e) {  // the 12 edges: 4 along each axis
          const axis = e >> 2, u = (axis + 1) % 3, w = (axis + 2) % 3;
          const p = [0, 0, 0], q = [0, 0, 0];
          p[u] = q[u] = c[u][e & 1];
          p[w] = q[w] = c[w][(e >> 1) & 1];
          p[axis] = c[axis][0];
          q[axis] = c[axis][1];
          pts.push(new THREE.Vector3(...p), new THREE.Vector3(...q));
        }
      }
      const ctx = new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(pts),
        material('context', '#8c959f', 0.35, () => new THREE.LineBasicMaterial({
          color: '#8c959f', transparent: true, opacity: 0.35 })));
      ctx.name = 'context';
      ctx.visible = $('show-context').checked;
      gl.group.add(ctx);
    }
    gl.fitBox = fit;
    gl.viewDir = dir;
    // First look: both parts whole, centred on the finding's `at` (Zoom to
    // overlap, O, comes closer).
    fitTo(gl.partBoxes, dir, gl.atPoint);
  }

  // Looks from across `dir` (so the depth arrow is seen side-on) with every
  // box of `boxes` wholly in view: the camera backs off until each box corner
  // is within the canvas's angles of view. Centred on `at` when given (the
  // finding's point), else on the boxes' middle.
  function fitTo(boxes, dir, at) {
    if (!gl || !boxes || !boxes.length) return;
    const all = new THREE.Box3();
    for (const b of boxes) all.union(b);
    const centre = at ? at.clone() : all.getCenter(new THREE.Vector3());
    const corners = [];
    for (const b of boxes)
      for (let c = 0; c < 8; ++c)
        corners.push(new THREE.Vector3(c & 1 ? b.max.x : b.min.x, c & 2 ? b.max.y : b.min.y,
          c & 4 ? b.max.z : b.min.z).sub(centre));
    const radius = Math.max(1e-9, ...corners.map((p) => p.length()));
    // The marker keeps its size on screen: 1/40 of the view's radius.
    if (gl.marker) gl.marker.scale.setScalar(radius / 40);
    let side = new THREE.Vector3(1, 0.6, 0.8);
    if (dir) {
      const up = Math.abs(dir.z) < 0.9 ? new THREE.Vector3(0, 0, 1) : new THREE.Vector3(1, 0, 0);
      side = new THREE.Vector3().crossVectors(dir, up).normalize().addScaledVector(up, 0.45).addScaledVector(dir, 0.25);
    }
    side.normalize();
    // The camera's axes as lookAt makes them (up +z), and the half-angles of view.
    const camUp = new THREE.Vector3(0, 0, 1);
    const right = new THREE.Vector3().crossVectors(camUp, side);
    if (right.lengthSq() < 1e-12) right.set(1, 0, 0);
    right.normalize();
    const upward = new THREE.Vector3().crossVectors(side, right);
    const tanV = Math.tan((gl.camera.fov / 2) * Math.PI / 180), tanH = tanV * gl.camera.aspect;
    let dist = 1e-9;
    for (const p of corners)
      dist = Math.max(dist, p.dot(side) + Math.max(Math.abs(p.dot(right)) / tanH, Math.abs(p.dot(upward)) / tanV));
    dist *= 1.08;
    gl.camera.position.copy(centre).addScaledVector(side, dist);
    gl.camera.near = Math.max(dist - radius, dist / 1000) / 10;
    gl.camera.far = dist + radius * 10;
    gl.camera.up.copy(camUp);
    gl.camera.updateProjectionMatrix();
    gl.controls.target.copy(centre);
    gl.controls.update();
    // Where the view is centred, in scene units, and how far the parts reach on
    // screen (-1..1 is the canvas's edge), for tests.
    api.target = [centre.x + gl.centre[0], centre.y + gl.centre[1], centre.z + gl.centre[2]];
    api.marker = !!gl.marker;
    api.partsOnScreen = partsOnScreen();
    render();
  }

  // The largest |x| and |y| of the shown parts' vertices in normalised device
  // coordinates: at most 1 when both parts are wholly in view.
  function partsOnScreen() {
    gl.camera.updateMatrixWorld();
    let reach = 0;
    const p = new THREE.Vector3();
    for (const name of ['a', 'b']) {
      const obj = gl.group.getObjectByName(name);
      if (!obj) continue;
      obj.updateMatrixWorld();
      const mesh = obj.children[0];
      const pos = mesh.geometry.getAttribute('position');
      for (let k = 0; k < pos.count; ++k) {
        p.fromBufferAttribute(pos, k).applyMatrix4(mesh.matrixWorld).project(gl.camera);
        reach = Math.max(reach, Math.abs(p.x), Math.abs(p.y));
      }
    }
    return reach;
  }

  function toggle(name, on) {
    if (!gl) return;
    for (const c of gl.group.children) if (c.name === name) c.visible = on;
    render();
  }

  // ---- Histogram ----
  function histogram() {
    const depths = findings.filter((f) => f.depth > 0).map((f) => f.depth);
    const plot = $('histogram-plot');
    const tol = data.tolerance;
    if (!depths.length) {
      $('histogram-text').textContent = 'No positive depths.';
      return;
    }
    let lo = Math.min(...depths, tol), hi = Math.max(...depths, tol);
    const logScale = hi / lo > 50;
    const tx = logScale ? Math.log10 : (x) => x;
    lo = tx(lo); hi = tx(hi);
    if (hi - lo < 1e-12) { lo -= 0.5; hi += 0.5; }
    const pad = (hi - lo) * 0.04;
    lo -= pad; hi += pad;
    const bins = 30, counts = new Array(bins).fill(0);
    for (const d of depths) counts[Math.min(bins - 1, Math.floor(((tx(d) - lo) / (hi - lo)) * bins))]++;
    const W = 900, H = 190, L = 40, B = 30, T = 10, max = Math.max(...counts);
    const X = (t) => L + ((t - lo) / (hi - lo)) * (W - L - 10);
    const ns = 'http://www.w3.org/2000/svg';
    const svg = document.createElementNS(ns, 'svg');
    svg.setAttribute('viewBox', '0 0 ' + W + ' ' + H);
    svg.setAttribute('role', 'img');
    const mk = (tag, attrs, text) => {
      const e = document.createElementNS(ns, tag);
      for (const k in attrs) e.setAttribute(k, attrs[k]);
      if (text !== undefined) e.textContent = text;
      svg.append(e);
      return e;
    };
    const tolT = tx(tol);
    counts.forEach((c, i) => {
      if (!c) return;
      const x0 = X(lo + ((hi - lo) * i) / bins), x1 = X(lo + ((hi - lo) * (i + 1)) / bins);
      const h = ((H - B - T) * c) / max;
      const r = mk('rect', { x: x0 + 0.5, y: H - B - h, width: Math.max(1, x1 - x0 - 1), height: h,
        class: 'bar' + (lo + ((hi - lo) * (i + 0.5)) / bins > tolT ? ' over' : '') });
      const t = document.createElementNS(ns, 'title');
      t.textContent = c + ' finding(s)';
      r.append(t);
    });
    mk('line', { x1: L, x2: W - 10, y1: H - B, y2: H - B, stroke: '#888' });
    mk('line', { x1: X(tolT), x2: X(tolT), y1: T, y2: H - B, class: 'tol' });
    mk('text', { x: X(tolT) + 4, y: T + 10 }, 'tolerance ' + len(tol));
    for (let i = 0; i <= 4; ++i) {
      const t = lo + ((hi - lo) * i) / 4;
      mk('text', { x: X(t), y: H - B + 14, 'text-anchor': 'middle' }, num(logScale ? Math.pow(10, t) : t, 3));
    }
    mk('text', { x: L, y: H - 2 }, 'depth (' + units + (logScale ? ', log scale' : '') + ')');
    mk('text', { x: 4, y: T + 10 }, String(max));
    svg.setAttribute('aria-label', 'Histogram of ' + depths.length + ' depths; tolerance ' + len(tol));
    plot.append(svg);
    const under = findings.filter((f) => f.depth > 0 && f.depth <= tol);
    let text = depths.length + ' positive depths: ' + under.length + ' at or below the tolerance, ' +
      (depths.length - under.length) + ' above it.';
    if (under.length) {
      const closest = Math.min(...under.map((f) => tol - f.depth));
      text += ' The closest false positive is ' + len(closest) + ' below the tolerance.';
    }
    $('histogram-text').textContent = text;
  }

  // ---- Start ----
  api.ms.script_start = Math.round(t0);
  summary();
  buildTable();
  buildGroups();
  applyFilter();
  lap('table');
  histogram();
  lap('histogram');
  if (window.THREE) $('three-rev').textContent = 'r' + THREE.REVISION;
  gl = initGl();
  lap('webgl');
  api.webgl = !!gl;
  $('fit').addEventListener('click', () => gl && fitTo(gl.partBoxes, gl.viewDir));
  $('zoom-overlap').addEventListener('click', () => gl && fitTo(gl.overlapBox ? [gl.overlapBox] : gl.partBoxes, gl.viewDir, gl.atPoint));
  $('show-a').addEventListener('change', (e) => toggle('a', e.target.checked));
  $('show-b').addEventListener('change', (e) => toggle('b', e.target.checked));
  $('show-context').addEventListener('change', (e) => toggle('context', e.target.checked));
  document.addEventListener('keydown', (e) => {
    if (e.target.tagName === 'INPUT' || e.target.tagName === 'SELECT') return;
    if (e.key === 'f' || e.key === 'F') $('fit').click();
    if (e.key === 'o' || e.key === 'O') $('zoom-overlap').click();
  });
  window.addEventListener('hashchange', fromHash);
  if (!fromHash() && findings.length) select(0, false, false);
  lap('first_view');
  if (!findings.length) $('view-title').textContent = 'No findings: nothing to show in 3D';
  api.readyMs = performance.now();
  api.ready = true;
})();
