// Layout primitives: breaking cycles, layers, order in a layer, stacking a layer, and
// the force layout option. compound.js puts them together for nested namespace boxes.

const ROW_GAP = 12;
const DUMMY_GAP = 5;
const DUMMY_H = 2;
const BOX_GAP = 26;
const SWEEPS = 8;

// The pairs that point back up a DFS of these pairs (reversing them leaves no cycle).
function backEdges(vertices, pairs) {
  const out = new Map(vertices.map(v => [v, []]));
  for (const p of pairs) if (out.has(p.a) && out.has(p.b)) out.get(p.a).push(p);
  const state = new Map(), back = new Set();
  for (const root of vertices) {
    if (state.has(root)) continue;
    const frames = [[root, 0]];
    state.set(root, 1);
    while (frames.length) {
      const frame = frames[frames.length - 1];
      const [v, i] = frame;
      const next = out.get(v);
      if (i >= next.length) { state.set(v, 2); frames.pop(); continue; }
      frame[1] = i + 1;
      const w = next[i].b;
      if (!state.has(w)) { state.set(w, 1); frames.push([w, 0]); }
      else if (state.get(w) === 1) back.add(next[i]);
    }
  }
  return back;
}

// Longest-path layers over a topological order of these pairs, then every source
// pulled right, next to its nearest consumer.
function layering(vertices, pairs) {
  const out = new Map(), inc = new Map();
  for (const v of vertices) { out.set(v, []); inc.set(v, []); }
  for (const [a, b] of pairs) { out.get(a).push(b); inc.get(b).push(a); }
  const order = topologicalOrder(vertices, out, inc);
  const layer = new Map();
  for (const v of order) {
    let l = 0;
    for (const u of inc.get(v)) l = Math.max(l, layer.get(u) + 1);
    layer.set(v, l);
  }
  for (const v of order.slice().reverse()) {
    if (inc.get(v).length === 0 && out.get(v).length > 0) {
      let l = Infinity;
      for (const w of out.get(v)) l = Math.min(l, layer.get(w) - 1);
      layer.set(v, Math.max(0, l));
    }
  }
  return layer;
}

function topologicalOrder(vertices, out, inc) {
  const degree = new Map(vertices.map(v => [v, inc.get(v).length]));
  const queue = vertices.filter(v => degree.get(v) === 0);
  const order = [];
  for (let i = 0; i < queue.length; i++) {
    const v = queue[i];
    order.push(v);
    for (const w of out.get(v)) {
      degree.set(w, degree.get(w) - 1);
      if (degree.get(w) === 0) queue.push(w);
    }
  }
  return order;
}


// Rows of each layer ordered by barycentre sweeps, down then up; ties by label in
// natural order (ranked once here).
function orderLayers(vertices, layer, out, inc) {
  const count = Math.max(0, ...vertices.map(v => layer.get(v))) + 1;
  const layers = Array.from({length: count}, () => []);
  for (const v of vertices) layers[layer.get(v)].push(v);
  const rank = new Map();
  vertices.filter(v => !v.dummy).sort((a, b) => compareText(a.label, b.label) || compareText(a.id, b.id))
    .forEach((v, i) => rank.set(v, i));
  const byRank = (a, b) => (rank.get(a) ?? Infinity) - (rank.get(b) ?? Infinity);
  for (const row of layers) row.sort(byRank);
  const pos = new Map();
  layers.forEach(row => row.forEach((v, i) => pos.set(v, i)));
  for (let sweep = 0; sweep < SWEEPS; sweep++) {
    const down = sweep % 2 === 0;
    const range = down ? [...Array(count).keys()].slice(1) : [...Array(count).keys()].reverse().slice(1);
    for (const l of range) {
      const row = layers[l];
      const bary = new Map();
      for (const v of row) {
        const near = (down ? inc.get(v) : out.get(v)).filter(u => layer.get(u) !== l);
        bary.set(v, near.length ? mean(near.map(u => pos.get(u))) : pos.get(v));
      }
      row.sort((a, b) => bary.get(a) - bary.get(b) || byRank(a, b));
      row.forEach((v, i) => pos.set(v, i));
    }
  }
  return layers;
}

// y of each vertex of a row, as near as may be to what it wants, in order, with gaps
// (wider around boxes, narrow between dummies and ports).
function stack(row, want) {
  const y = [];
  const thin = v => v.dummy || v.port;
  const boxy = v => v.kind === 'box' || v.kind === 'namespace';
  for (let i = 0; i < row.length; i++) {
    if (i === 0) { y.push(want[0]); continue; }
    const prev = row[i - 1], v = row[i];
    const gap = (thin(prev) && thin(v) ? DUMMY_GAP : boxy(prev) || boxy(v) ? BOX_GAP : ROW_GAP) + (prev.h + v.h) / 2;
    y.push(Math.max(want[i], y[i - 1] + gap));
  }
  const shift = mean(want.map((w, i) => w - y[i]));
  row.forEach((v, i) => { v.y = y[i] + shift; });
}

function meanY(list) {
  let sum = 0;
  for (const v of list) sum += v.y;
  return sum / list.length;
}

function mean(list) {
  let sum = 0;
  for (const x of list) sum += x;
  return list.length ? sum / list.length : 0;
}

// Natural order: /robot2/ before /robot10/.
const COLLATOR = new Intl.Collator('en', {numeric: true});
function compareText(a, b) {
  return COLLATOR.compare(String(a || ''), String(b || ''));
}

function forceLayout(vertices, edges, onTick, opts) {
  // Start from the layered positions so the force layout settles quickly; edges are drawn
  // straight, without the layered layout's dummy points.
  layeredLayout(vertices, edges, opts);
  for (const e of edges) e.points = null;
  const sim = d3.forceSimulation(vertices)
    .force('link', d3.forceLink(edges).distance(80).strength(0.4))
    .force('charge', d3.forceManyBody().strength(-260).distanceMax(600))
    .force('collide', d3.forceCollide(v => v.w / 2 + 6).iterations(2))
    .alphaDecay(0.05)
    .on('tick', onTick);
  return sim;
}
