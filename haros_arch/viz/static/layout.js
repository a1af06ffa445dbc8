// Layered layout (data flows left to right) and the force layout option.
//
// layered: cycles are broken by reversing DFS back edges; layers by longest path, then
// every source is pulled next to its first consumer (a parameter sits beside its reader);
// when links across namespaces would make the flow far deeper than inside any of them,
// each namespace's lane is layered on its own links (and starts at the left);
// an edge spanning several layers gets one dummy point in each layer it crosses, so it
// takes a slot in that column and runs between vertices instead of across them; order in
// a layer by barycentre sweeps (dummies included), members of a namespace kept together;
// y by the mean position of neighbours, pushed apart to keep the order and the gaps.
// Each edge gets e.points: where it enters and leaves each column it crosses, from its
// source to its target.
//
// Collapsed namespaces that would stretch over many layers (a fleet of robots that call
// each other) are set out instead as a grid in natural name order, shaped for the stage
// (opts.aspect = width / height), as a lane of their own.

const LAYER_GAP = 90;
const ROW_GAP = 12;
const DUMMY_GAP = 5;
const DUMMY_H = 2;
const GROUP_GAP = 26;
const LANE_GAP = 44;
const LANE_LABEL = 30;
const WRAP_LAYERS = 6;
const GRID_GAP_X = 70;
const GRID_GAP_Y = 46;
const GRID = '\u0001grid';
const MAX_DEPTH = 30;

function layeredLayout(vertices, edges, opts = {}) {
  for (const e of edges) e.points = null;
  for (const v of vertices) v.lane = v.group;
  if (!vertices.length) return;
  const out = new Map(), inc = new Map();
  for (const v of vertices) { out.set(v, []); inc.set(v, []); }
  const {dag, pairOf} = acyclicEdges(vertices, edges, out);

  let layer = layering(vertices, dag);
  const boxes = vertices.filter(v => v.kind === 'namespace');
  const wrap = boxes.length > 0 && new Set(boxes.map(v => layer.get(v))).size > WRAP_LAYERS;
  if (wrap) for (const v of boxes) v.lane = GRID;
  // When links between namespaces chain them into a flow far deeper than any one
  // namespace's own, each namespace is layered on its own links only.
  const inside = dag.filter(([a, b]) => a.lane === b.lane);
  const local = layering(vertices, inside);
  const deepest = map => Math.max(...vertices.map(v => map.get(v))) + 1;
  const separate = deepest(layer) > Math.max(MAX_DEPTH, 2 * deepest(local));
  if (separate) layer = local;
  // Long edges: a chain of dummies, one per crossed layer; the first half in the lane
  // of the edge's tail, the second in the lane of its head. Chains from one tail share
  // their dummies while they are in the same lane: a trunk that branches.
  const chains = new Map();
  for (const v of vertices) out.set(v, []);
  for (const v of vertices) inc.set(v, []);
  const link = (a, b) => { if (!out.get(a).includes(b)) { out.get(a).push(b); inc.get(b).push(a); } };
  const all = vertices.slice();
  const shared = new Map();
  for (const [a, b] of dag) {
    const la = layer.get(a), lb = layer.get(b);
    if (lb - la <= 1 || a.lane === GRID || b.lane === GRID || (separate && a.lane !== b.lane)) {
      link(a, b);
      continue;
    }
    if (!shared.has(a)) shared.set(a, new Map());
    const trunk = shared.get(a);
    const chain = [];
    let prev = a;
    for (let l = la + 1; l < lb; l++) {
      const group = l - la <= (lb - la) / 2 ? a.group : b.group;
      const key = group === a.group ? l : l + '\u0000' + b.id;
      let d = trunk.get(key);
      if (!d) {
        d = {id: '', dummy: true, group, lane: group, label: '', w: 0, h: DUMMY_H, x: 0, y: 0};
        out.set(d, []); inc.set(d, []); layer.set(d, l); all.push(d);
        trunk.set(key, d);
      }
      link(prev, d); chain.push(d); prev = d;
    }
    link(prev, b);
    chains.set(a, (chains.get(a) || new Map()).set(b, chain));
  }

  const count = Math.max(...vertices.map(v => layer.get(v))) + 1;
  const layers = Array.from({length: count}, () => []);
  for (const v of all) layers[layer.get(v)].push(v);
  // Ties are broken by namespace, then label, in natural order: ranked once here.
  const rank = new Map();
  vertices.slice().sort((a, b) => compareText(a.group, b.group) || compareText(a.label, b.label))
    .forEach((v, i) => rank.set(v, i));
  const groupRank = new Map([...new Set(vertices.map(v => v.group))].sort(compareText).map((g, i) => [g, i]));
  for (const row of layers) row.sort((a, b) => groupRank.get(a.group) - groupRank.get(b.group) || (rank.get(a) ?? Infinity) - (rank.get(b) ?? Infinity) || 0);

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
      sortRow(row, bary, rank, groupRank);
      row.forEach((v, i) => pos.set(v, i));
    }
  }

  // x: columns as wide as their widest vertex.
  let x = 0;
  for (const row of layers) {
    const width = Math.max(...row.map(v => v.w));
    for (const v of row) { v.x = x + width / 2; v.colW = width; }
    x += width + LAYER_GAP;
  }
  // y: one horizontal lane per namespace, stacked; inside a lane each layer moves toward
  // its neighbours' mean position, keeping its order and gaps.
  const lanes = new Map();
  for (const row of layers) {
    row.forEach((v, i) => {
      if (!lanes.has(v.lane)) lanes.set(v.lane, {name: v.lane, rows: layers.map(() => []), rank: []});
      const lane = lanes.get(v.lane);
      lane.rows[layer.get(v)].push(v);
      if (!v.dummy) lane.rank.push((i + 0.5) / row.length);
    });
  }
  const ordered = [...lanes.values()].sort((a, b) => (separate ? 0 : mean(a.rank) - mean(b.rank)) || compareText(a.name, b.name));
  const blocks = [];
  for (const lane of ordered) {
    const rows = lane.rows.filter(row => row.length);
    const members = rows.flat();
    if (lane.name === GRID) {
      blocks.push({members, height: grid(members, 0, opts.aspect || 1.6)});
      continue;
    }
    const same = new Map();
    for (const row of rows) for (const v of row) same.set(v, [...inc.get(v), ...out.get(v)].filter(u => u.lane === lane.name));
    for (const row of rows) stack(row, row.map((_, i) => i * 40));
    for (let pass = 0; pass < 4; pass++) {
      for (const row of pass % 2 === 0 ? rows : rows.slice().reverse()) {
        stack(row, row.map(v => { const near = same.get(v); return near.length ? meanY(near) : v.y; }));
      }
    }
    const low = Math.min(...members.map(v => v.y - v.h / 2));
    const shift = (lane.name ? LANE_LABEL : 0) - low;  // '' is the root namespace
    for (const v of members) v.y += shift;
    blocks.push({members, height: Math.max(...members.map(v => v.y + v.h / 2))});
  }
  // Lanes are stacked; lanes layered each on its own start at the left, so they are set
  // in as many columns as make the whole largest on the stage.
  for (const b of blocks) {
    b.left = Math.min(...b.members.map(v => v.x - (v.colW || v.w) / 2));
    b.width = Math.max(...b.members.map(v => v.x + (v.colW || v.w) / 2)) - b.left;
  }
  const columns = separate ? packColumns(blocks, opts.aspect || 1.6) : [blocks];
  let left = 0;
  for (const column of columns) {
    let top = 0;
    for (const b of column) {
      const dx = separate ? left - b.left : 0;
      for (const v of b.members) { v.y += top; v.x += dx; }
      top += b.height + LANE_GAP;
    }
    left += Math.max(...column.map(b => b.width)) + LANE_GAP * 2;
  }

  // Each edge follows the chain of its pair (reversed when the edge was turned around),
  // straight across each column it crosses; edges of the grid are free curves.
  for (const e of edges) {
    const pair = pairOf.get(e);
    if (!pair || e.source.lane === GRID || e.target.lane === GRID) continue;
    const chain = (chains.get(pair[0]) || new Map()).get(pair[1]) || [];
    const forward = pair[0] === e.source;
    e.points = (forward ? chain : chain.slice().reverse()).flatMap(d => forward
      ? [[d.x - d.colW / 2, d.y], [d.x + d.colW / 2, d.y]] : [[d.x + d.colW / 2, d.y], [d.x - d.colW / 2, d.y]]);
  }
}

// Blocks in order, split into columns of about equal height; the number of columns
// that makes the whole largest on a stage of this aspect.
function packColumns(blocks, aspect) {
  const total = blocks.reduce((sum, b) => sum + b.height + LANE_GAP, 0);
  let best = [blocks], bestScale = 0;
  for (let k = 1; k <= Math.min(blocks.length, 12); k++) {
    const target = Math.max(total / k, ...blocks.map(b => b.height));
    const columns = [[]];
    let height = 0;
    for (const b of blocks) {
      if (height > 0 && height + b.height > target) { columns.push([]); height = 0; }
      columns[columns.length - 1].push(b);
      height += b.height + LANE_GAP;
    }
    const width = columns.reduce((sum, c) => sum + Math.max(...c.map(b => b.width)) + LANE_GAP * 2, 0);
    const tall = Math.max(...columns.map(c => c.reduce((sum, b) => sum + b.height + LANE_GAP, 0)));
    const scale = Math.min(aspect / width, 1 / tall);
    if (scale > bestScale) { bestScale = scale; best = columns; }
  }
  return best;
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

// Boxes by name, in as many columns as make them largest on a stage of this aspect;
// returns the bottom of the grid.
function grid(boxes, top, aspect) {
  boxes.sort((a, b) => compareText(a.name, b.name));
  const cw = Math.max(...boxes.map(v => v.w)) + GRID_GAP_X, ch = Math.max(...boxes.map(v => v.h)) + GRID_GAP_Y;
  let columns = 1, best = 0;
  for (let c = 1; c <= boxes.length; c++) {
    const scale = Math.min(aspect / (c * cw), 1 / (Math.ceil(boxes.length / c) * ch));
    if (scale > best) { best = scale; columns = c; }
  }
  boxes.forEach((v, i) => {
    v.x = (i % columns) * cw + cw / 2;
    v.y = top + Math.floor(i / columns) * ch + v.h / 2;
  });
  return top + Math.ceil(boxes.length / columns) * ch - GRID_GAP_Y;
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
  const seen = new Map(), dag = [], pairOf = new Map();
  for (const e of edges) {
    const back = reversed.has(e.source.id + '\u0000' + e.target.id);
    const pair = back ? [e.target, e.source] : [e.source, e.target];
    const key = pair[0].id + '\u0000' + pair[1].id;
    if (pair[0] === pair[1]) continue;
    if (!seen.has(key)) { seen.set(key, pair); dag.push(pair); }
    pairOf.set(e, seen.get(key));
  }
  return {dag, pairOf};
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

function sortRow(row, bary, rank, groupRank) {
  // Keep a namespace's members together: order groups by their mean barycentre (each
  // vertex outside a namespace is a group of its own).
  const sums = new Map(), key = new Map();
  for (const v of row) {
    const k = v.group || v;
    key.set(v, k);
    const sum = sums.get(k) || [0, 0];
    sum[0] += bary.get(v); sum[1] += 1;
    sums.set(k, sum);
  }
  const at = new Map(row.map(v => { const [total, n] = sums.get(key.get(v)); return [v, total / n]; }));
  row.sort((a, b) => at.get(a) - at.get(b) || groupRank.get(a.group) - groupRank.get(b.group) ||
    bary.get(a) - bary.get(b) || (rank.get(a) ?? Infinity) - (rank.get(b) ?? Infinity) || 0);
}

function stack(row, want) {
  const y = [];
  for (let i = 0; i < row.length; i++) {
    if (i === 0) { y.push(want[0]); continue; }
    const prev = row[i - 1], v = row[i];
    const near = prev.dummy && v.dummy ? DUMMY_GAP : ROW_GAP;
    const gap = (prev.group !== v.group ? GROUP_GAP : near) + (prev.h + v.h) / 2;
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

function forceLayout(vertices, edges, onTick) {
  // Start from the layered positions so the force layout settles quickly; edges are drawn
  // straight, without the layered layout's dummy points.
  layeredLayout(vertices, edges);
  for (const e of edges) e.points = null;
  const sim = d3.forceSimulation(vertices)
    .force('link', d3.forceLink(edges).distance(80).strength(0.4))
    .force('charge', d3.forceManyBody().strength(-260).distanceMax(600))
    .force('collide', d3.forceCollide(v => v.w / 2 + 6).iterations(2))
    .alphaDecay(0.05)
    .on('tick', onTick);
  return sim;
}
