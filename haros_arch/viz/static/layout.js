// Layered layout (data flows left to right) and the force layout option.
//
// layered: cycles are broken by reversing DFS back edges; layers by longest path, then
// every source is pulled next to its first consumer (a parameter sits beside its reader);
// order in a layer by barycentre sweeps, members of a namespace kept together; y by the
// mean position of neighbours, pushed apart to keep the order and the gaps.

const LAYER_GAP = 90;
const ROW_GAP = 12;
const GROUP_GAP = 26;
const LANE_GAP = 44;
const LANE_LABEL = 30;

function layeredLayout(vertices, edges) {
  if (!vertices.length) return;
  const out = new Map(), inc = new Map();
  for (const v of vertices) { out.set(v, []); inc.set(v, []); }
  const dag = acyclicEdges(vertices, edges, out);
  for (const v of vertices) out.set(v, []);
  for (const [a, b] of dag) { out.get(a).push(b); inc.get(b).push(a); }

  // Longest-path layering over a topological order.
  const order = topologicalOrder(vertices, out, inc);
  const layer = new Map();
  for (const v of order) {
    let l = 0;
    for (const u of inc.get(v)) l = Math.max(l, layer.get(u) + 1);
    layer.set(v, l);
  }
  // Pull sources right, next to their nearest consumer.
  for (const v of order.slice().reverse()) {
    if (inc.get(v).length === 0 && out.get(v).length > 0) {
      let l = Infinity;
      for (const w of out.get(v)) l = Math.min(l, layer.get(w) - 1);
      layer.set(v, Math.max(0, l));
    }
  }
  const count = Math.max(...layer.values()) + 1;
  const layers = Array.from({length: count}, () => []);
  for (const v of vertices) layers[layer.get(v)].push(v);
  for (const row of layers) row.sort((a, b) => compareText(a.group, b.group) || compareText(a.label, b.label));

  // Barycentre sweeps, down then up.
  const pos = new Map();
  const index = () => layers.forEach(row => row.forEach((v, i) => pos.set(v, i)));
  index();
  for (let sweep = 0; sweep < 8; sweep++) {
    const down = sweep % 2 === 0;
    const range = down ? [...Array(count).keys()].slice(1) : [...Array(count).keys()].reverse().slice(1);
    for (const l of range) {
      const row = layers[l];
      const bary = new Map();
      for (const v of row) {
        const near = (down ? inc.get(v) : out.get(v)).filter(u => layer.get(u) !== l);
        bary.set(v, near.length ? mean(near.map(u => pos.get(u))) : pos.get(v));
      }
      sortRow(row, bary);
      row.forEach((v, i) => pos.set(v, i));
    }
  }

  // x: columns as wide as their widest vertex.
  let x = 0;
  for (const row of layers) {
    const width = Math.max(...row.map(v => v.w));
    for (const v of row) v.x = x + width / 2;
    x += width + LAYER_GAP;
  }
  // y: one horizontal lane per namespace, stacked; inside a lane each layer moves toward
  // its neighbours' mean position, keeping its order and gaps.
  const lanes = new Map();
  for (const row of layers) {
    row.forEach((v, i) => {
      if (!lanes.has(v.group)) lanes.set(v.group, {name: v.group, rows: layers.map(() => []), rank: []});
      const lane = lanes.get(v.group);
      lane.rows[layer.get(v)].push(v);
      lane.rank.push((i + 0.5) / row.length);
    });
  }
  const ordered = [...lanes.values()].sort((a, b) => mean(a.rank) - mean(b.rank) || compareText(a.name, b.name));
  let top = 0;
  for (const lane of ordered) {
    const rows = lane.rows.filter(row => row.length);
    const same = v => [...inc.get(v), ...out.get(v)].filter(u => u.group === lane.name);
    for (const row of rows) stack(row, row.map((_, i) => i * 40));
    for (let pass = 0; pass < 4; pass++) {
      for (const row of pass % 2 === 0 ? rows : rows.slice().reverse()) {
        stack(row, row.map(v => { const near = same(v); return near.length ? mean(near.map(u => u.y)) : v.y; }));
      }
    }
    const members = rows.flat();
    const low = Math.min(...members.map(v => v.y - v.h / 2));
    const shift = top + (lane.name ? LANE_LABEL : 0) - low;
    for (const v of members) v.y += shift;
    top = Math.max(...members.map(v => v.y + v.h / 2)) + LANE_GAP;
  }
}

function acyclicEdges(vertices, edges, out) {
  for (const e of edges) out.get(e.source).push(e.target);
  const state = new Map(), reversed = new Set();
  for (const root of vertices) {
    if (state.has(root)) continue;
    const stackFrames = [[root, 0]];
    state.set(root, 1);
    while (stackFrames.length) {
      const frame = stackFrames[stackFrames.length - 1];
      const [v, i] = frame;
      const next = out.get(v);
      if (i >= next.length) { state.set(v, 2); stackFrames.pop(); continue; }
      frame[1] = i + 1;
      const w = next[i];
      if (!state.has(w)) { state.set(w, 1); stackFrames.push([w, 0]); }
      else if (state.get(w) === 1) reversed.add(v.id + '\u0000' + w.id);
    }
  }
  const seen = new Set(), dag = [];
  for (const e of edges) {
    const back = reversed.has(e.source.id + '\u0000' + e.target.id);
    const pair = back ? [e.target, e.source] : [e.source, e.target];
    const key = pair[0].id + '\u0000' + pair[1].id;
    if (pair[0] !== pair[1] && !seen.has(key)) { seen.add(key); dag.push(pair); }
  }
  return dag;
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

function sortRow(row, bary) {
  // Keep a namespace's members together: order groups by their mean barycentre.
  const groups = new Map();
  for (const v of row) {
    const key = v.group || '\u0000' + v.id;
    if (!groups.has(key)) groups.set(key, []);
    groups.get(key).push(bary.get(v));
  }
  const groupBary = new Map([...groups].map(([k, list]) => [k, mean(list)]));
  row.sort((a, b) => {
    const ga = groupBary.get(a.group || '\u0000' + a.id), gb = groupBary.get(b.group || '\u0000' + b.id);
    return ga - gb || compareText(a.group, b.group) || bary.get(a) - bary.get(b) || compareText(a.label, b.label);
  });
}

function stack(row, want) {
  const y = [];
  for (let i = 0; i < row.length; i++) {
    if (i === 0) { y.push(want[0]); continue; }
    const prev = row[i - 1], v = row[i];
    const gap = (prev.group !== v.group ? GROUP_GAP : ROW_GAP) + (prev.h + v.h) / 2;
    y.push(Math.max(want[i], y[i - 1] + gap));
  }
  const shift = mean(want.map((w, i) => w - y[i]));
  row.forEach((v, i) => { v.y = y[i] + shift; });
}

function mean(list) {
  let sum = 0;
  for (const x of list) sum += x;
  return list.length ? sum / list.length : 0;
}

// Natural order: /robot2/ before /robot10/.
function compareText(a, b) {
  return String(a || '').localeCompare(String(b || ''), 'en', {numeric: true});
}

function forceLayout(vertices, edges, onTick) {
  // Start from the layered positions so the force layout settles quickly.
  layeredLayout(vertices, edges);
  const sim = d3.forceSimulation(vertices)
    .force('link', d3.forceLink(edges).distance(80).strength(0.4))
    .force('charge', d3.forceManyBody().strength(-260).distanceMax(600))
    .force('collide', d3.forceCollide(v => v.w / 2 + 6).iterations(2))
    .alphaDecay(0.05)
    .on('tick', onTick);
  return sim;
}
