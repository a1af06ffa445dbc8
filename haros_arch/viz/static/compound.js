// The layered layout of nested namespace boxes (data flows left to right).
//
// Each open box is laid out on its own, as one item of the box around it (or of the
// root): so opening or closing a box changes its size but not the layers or the order
// of anything outside it. An edge is laid out in the innermost box holding both ends,
// between the items that hold them; where it leaves a box it goes through a port on the
// box's border (on the side facing where it goes, one port per outside item, shared by
// every edge to it), which the box's own layout places in a column of its own. In every
// box an edge that spans several layers takes one dummy point per layer it crosses, so
// edges run between items, never across another element or another box, and bend only
// in the gaps between columns. e.points: where the edge enters and leaves each column
// (and box border) it crosses, from source to target.
//
// Boxes (open or collapsed) that would stretch over many layers, or make a strip several
// times wider than the stage (a fleet of robots that call each other) are set out instead
// as rows in natural name order shaped for the
// stage (opts.aspect = width / height); their edges are free curves.

const LAYER_GAP = 90;
const PORT_GAP = 40;
const WRAP_LAYERS = 6;
const WRAP_MIN = 4;  // ... or this many, when laid out in layers they would be too wide
const WIDE = 4;
const SHELF_GAP_X = 60;
const SHELF_GAP_Y = 44;
const BLOCK_GAP = 50;
const LOOSE_COLUMN = 12;  // more items than this with no link inside their box: several columns

function layeredLayout(vertices, edges, opts = {}) {
  for (const e of edges) e.points = null;
  const rects = new Map();
  if (!vertices.length) return rects;
  const levels = new Map(), boxItem = new Map(), home = new Map();
  const level = name => {
    if (!levels.has(name)) levels.set(name, {name, items: [], pairs: new Map(), ports: [], portFor: new Map()});
    return levels.get(name);
  };
  const labelOf = name => (opts.tree && opts.tree.boxes.get(name) ? opts.tree.boxes.get(name).label : name);
  for (const v of vertices) {
    let up = level('');
    for (const name of v.path || []) {
      const lv = level(name);
      if (!boxItem.has(name)) {
        const item = {id: 'namespace:' + name, box: name, kind: 'box', label: labelOf(name), w: 0, h: 0, x: 0, y: 0};
        boxItem.set(name, item);
        up.items.push(item);
        lv.item = item;
      }
      up = lv;
    }
    up.items.push(v);
    home.set(v, up);
  }
  // Each edge belongs to the innermost level holding both ends, between the items there.
  const holderIn = (v, name) => {
    const path = v.path || [], i = name ? path.indexOf(name) : -1;
    return i + 1 < path.length ? boxItem.get(path[i + 1]) : v;
  };
  for (const e of edges) {
    const ps = e.source.path || [], pt = e.target.path || [];
    let k = 0;
    while (k < ps.length && k < pt.length && ps[k] === pt[k]) k++;
    const lv = level(k ? ps[k - 1] : '');
    const a = holderIn(e.source, lv.name), b = holderIn(e.target, lv.name);
    if (a === b) continue;
    e.route = {level: lv, a, b};
    addPair(lv.pairs, a, b, e);
  }
  const root = level('');
  arrange(root, levels, boxItem, opts.aspect || 1.6, true);
  place(root, 0, 0, levels, rects);
  for (const e of edges) {
    const r = e.route;
    if (!r || r.level.free.has(r.a) || r.level.free.has(r.b)) continue;
    const out = r.a === e.source ? [] : exitPoints(e.source, r.a, r.b, levels, boxItem);
    const into = r.b === e.target ? [] : exitPoints(e.target, r.b, r.a, levels, boxItem).reverse();
    if (out && into) e.points = [...out, ...chainPoints(r.level, r.a, r.b), ...into];
  }
  return rects;
}

function addPair(pairs, a, b, e) {
  const key = a.id + '\u0000' + b.id;
  if (!pairs.has(key)) pairs.set(key, {a, b, edges: []});
  pairs.get(key).edges.push(e);
}

// Layers, dummies and order of one level, then its boxes (with their ports) inside out,
// then coordinates relative to the level's top left corner; sets lv.w and lv.h.
function arrange(lv, levels, boxItem, aspect, isRoot) {
  const ports = lv.ports;
  const pairs = [...lv.pairs.values()];
  for (const p of ports) {
    for (const [item, list] of p.inner) pairs.push(p.side === 'left' ? {a: p, b: item, edges: list} : {a: item, b: p, edges: list});
  }
  const reversed = backEdges(lv.items, pairs.filter(p => !p.a.port && !p.b.port));
  const dag = pairs.map(p => reversed.has(p) ? [p.b, p.a, p] : [p.a, p.b, p]);
  const boxy = lv.items.filter(v => v.kind === 'box' || v.kind === 'namespace');
  const inner = dag.filter(([a, b]) => !a.port && !b.port);
  let layer = layering(lv.items, inner.map(([a, b]) => [a, b]));
  lv.free = new Set();
  const spread = new Set(boxy.map(v => layer.get(v))).size;
  if (boxy.length > 1 && (spread > WRAP_LAYERS || (spread >= WRAP_MIN && tooWide(lv.items, layer, aspect)))) {
    lv.free = new Set(boxy);
    const rest = lv.items.filter(v => !lv.free.has(v));
    layer = layering(rest, inner.filter(([a, b]) => !lv.free.has(a) && !lv.free.has(b)).map(([a, b]) => [a, b]));
  }
  const routed = dag.filter(([a, b]) => !lv.free.has(a) && !lv.free.has(b));
  spreadLoose(lv.items, routed.filter(([a, b]) => !a.port && !b.port), layer, lv.free, aspect);
  const left = ports.filter(p => p.side === 'left'), right = ports.filter(p => p.side === 'right');
  if (left.length) for (const [v, l] of layer) layer.set(v, l + 1);
  for (const p of left) layer.set(p, 0);
  const last = Math.max(0, ...[...layer.values()]);
  for (const p of right) layer.set(p, last + 1);

  // Long pairs: a chain of dummies; chains from one tail share their first half.
  const out = new Map(), inc = new Map(), shared = new Map();
  lv.chains = new Map();
  const laid = [...layer.keys()];
  for (const v of laid) { out.set(v, []); inc.set(v, []); }
  const link = (a, b) => { if (!out.get(a).includes(b)) { out.get(a).push(b); inc.get(b).push(a); } };
  for (const [a, b] of routed) {
    const la = layer.get(a), lb = layer.get(b), chain = [];
    let prev = a;
    if (!shared.has(a)) shared.set(a, new Map());
    for (let l = la + 1; l < lb; l++) {
      const key = l - la <= (lb - la) / 2 ? l : l + '\u0000' + b.id;
      let d = shared.get(a).get(key);
      if (!d) {
        d = {id: '', dummy: true, label: '', w: 0, h: DUMMY_H, x: 0, y: 0};
        shared.get(a).set(key, d); layer.set(d, l); laid.push(d); out.set(d, []); inc.set(d, []);
      }
      link(prev, d); chain.push(d); prev = d;
    }
    link(prev, b);
    lv.chains.set(a.id + '\u0000' + b.id, chain);
  }
  const layers = orderLayers(laid, layer, out, inc);

  // Ports of the boxes here: one per outside item, on the side facing it.
  for (const [a, b, pair] of routed) {
    for (const [c, other] of [[a, b], [b, a]]) {
      if (c.kind !== 'box') continue;
      const child = levels.get(c.box);
      let port = child.portFor.get(other.id);
      if (!port) {
        port = {id: 'port:' + c.box + '\u0000' + other.id, port: true, side: layer.get(other) > layer.get(c) ? 'right' : 'left',
                label: other.label || '', inner: new Map(), w: 0, h: 0, x: 0, y: 0};
        child.portFor.set(other.id, port);
        child.ports.push(port);
      }
      for (const e of pair.edges) {
        const end = (e.source.path || []).includes(c.box) ? e.source : e.target;
        const item = innerItem(end, c.box, boxItem);
        if (!port.inner.has(item)) port.inner.set(item, []);
        port.inner.get(item).push(e);
      }
    }
  }
  for (const v of lv.items) {
    if (v.kind !== 'box') continue;
    const child = levels.get(v.box);
    arrange(child, levels, boxItem, aspect, false);
    v.w = child.w; v.h = child.h;
  }
  coordinates(lv, layers, layer, out, inc, aspect, isRoot);
}

// Items linked to nothing else inside their level (a box of names each linked only to
// something outside it, through the box's ports, or to nothing) would all stand in one tall
// column. When they are many, they fill as many columns as give them about the stage's shape,
// in name order; their links reach them between the columns, as any link that crosses layers.
function spreadLoose(items, pairs, layer, free, aspect) {
  const linked = new Set(pairs.flatMap(([a, b]) => [a, b]));
  const loose = items.filter(v => !free.has(v) && !linked.has(v) && v.kind !== 'box' && v.kind !== 'namespace');
  if (loose.length <= LOOSE_COLUMN) return;
  const wide = Math.max(...loose.map(v => v.w)) + LAYER_GAP;
  const tall = loose.reduce((sum, v) => sum + v.h + ROW_GAP, 0);
  const columns = Math.min(loose.length, Math.max(1, Math.round(Math.sqrt(aspect * tall / wide))));
  const per = Math.ceil(loose.length / columns);
  loose.sort((a, b) => compareText(a.name || '', b.name || ''));
  loose.forEach((v, i) => layer.set(v, Math.floor(i / per)));
}

// Would these items, in these layers, make a strip much wider than the stage? Boxes
// count as one size whether open or not, so opening one never flips the decision.
function tooWide(items, layer, aspect) {
  const width = new Map(), height = new Map();
  for (const v of items) {
    const boxy = v.kind === 'box' || v.kind === 'namespace';
    const l = layer.get(v), w = boxy ? 300 : v.w, h = boxy ? 120 : v.h;
    width.set(l, Math.max(width.get(l) || 0, w));
    height.set(l, (height.get(l) || 0) + h + ROW_GAP);
  }
  const wide = [...width.values()].reduce((sum, w) => sum + w + LAYER_GAP, 0);
  return wide / Math.max(...height.values()) > WIDE * aspect;
}

function innerItem(v, name, boxItem) {
  const path = v.path || [], i = path.indexOf(name);
  return i + 1 < path.length ? boxItem.get(path[i + 1]) : v;
}

function coordinates(lv, layers, layer, out, inc, aspect, isRoot) {
  // x: columns as wide as their widest item; a column of ports sits closer.
  let x = 0;
  layers.forEach((row, l) => {
    if (!row.length) return;
    const width = Math.max(...row.map(v => v.w));
    for (const v of row) { v.x = x + width / 2; v.colW = width; }
    const portsOnly = row.every(v => v.port) || (layers[l + 1] || []).some(v => v.port);
    x += width + (portsOnly ? PORT_GAP : LAYER_GAP);
  });
  // y: each layer moves toward its neighbours' mean position, keeping order and gaps.
  const rows = layers.filter(row => row.length);
  const near = new Map();
  for (const row of rows) for (const v of row) near.set(v, [...inc.get(v), ...out.get(v)]);
  for (const row of rows) stack(row, row.map((_, i) => i * 40));
  for (let pass = 0; pass < 4; pass++) {
    for (const row of pass % 2 === 0 ? rows : rows.slice().reverse()) {
      stack(row, row.map(v => { const n = near.get(v); return n.length ? meanY(n) : v.y; }));
    }
  }
  const members = rows.flat();
  if (lv.free.size) {  // boxes set out in rows below what is layered
    const bottom = members.length ? Math.max(...members.map(v => v.y + v.h / 2)) + BLOCK_GAP : 0;
    const left = members.length ? Math.min(...members.map(v => v.x - v.w / 2)) : 0;
    shelves([...lv.free], left, bottom, aspect);
    members.push(...lv.free);
  }
  const pad = isRoot ? 0 : BOX_PAD + 4, top = isRoot ? 0 : BOX_TOP + 6;
  const x0 = Math.min(...members.map(v => (v.port ? v.x : v.x - v.w / 2 - pad)));
  const x1 = Math.max(...members.map(v => (v.port ? v.x : v.x + v.w / 2 + pad)));
  const y0 = Math.min(...members.map(v => v.y - v.h / 2)) - top;
  const y1 = Math.max(...members.map(v => v.y + v.h / 2)) + pad;
  for (const v of members) { v.x -= x0; v.y -= y0; }
  lv.members = members;
  lv.w = x1 - x0; lv.h = y1 - y0;
}

// Boxes in rows by name, the rows about as long as make the whole fit this aspect.
function shelves(boxes, left, top, aspect) {
  boxes.sort((a, b) => compareText(a.box || a.name, b.box || b.name));
  const area = boxes.reduce((sum, v) => sum + (v.w + SHELF_GAP_X) * (v.h + SHELF_GAP_Y), 0);
  const width = Math.max(...boxes.map(v => v.w), Math.sqrt(area * aspect));
  let x = 0, y = top, tall = 0;
  for (const v of boxes) {
    if (x > 0 && x + v.w > width) { x = 0; y += tall + SHELF_GAP_Y; tall = 0; }
    v.x = left + x + v.w / 2; v.y = y + v.h / 2;
    x += v.w + SHELF_GAP_X; tall = Math.max(tall, v.h);
  }
}

// Coordinates of a level and everything inside it made absolute; the rects of open boxes.
function place(lv, ox, oy, levels, rects) {
  for (const v of lv.members) {
    v.x += ox; v.y += oy;
    if (v.kind !== 'box') continue;
    const x0 = v.x - v.w / 2, y0 = v.y - v.h / 2;
    rects.set(v.box, {x0, y0, x1: x0 + v.w, y1: y0 + v.h});
    place(levels.get(v.box), x0, y0, levels, rects);
  }
}

// Points from vertex v (inside box item c) out through c's port toward `other`, to the
// edge of c's column.
function exitPoints(v, c, other, levels, boxItem) {
  const child = levels.get(c.box);
  const port = child.portFor.get(other.id);
  if (!port || child.free.size && child.free.has(innerItem(v, c.box, boxItem))) return null;
  const item = innerItem(v, c.box, boxItem);
  const deeper = item === v ? [] : exitPoints(v, item, port, levels, boxItem);
  if (!deeper) return null;
  const side = port.side === 'right' ? 1 : -1;
  return [...deeper, ...chainPoints(child, item, port), [port.x, port.y], [c.x + side * c.colW / 2, port.y]];
}

// The dummies between items a and b of a level, as points from a to b.
function chainPoints(lv, a, b) {
  const forward = lv.chains.get(a.id + '\u0000' + b.id);
  const chain = forward || lv.chains.get(b.id + '\u0000' + a.id) || [];
  const points = chain.flatMap(d => [[d.x - d.colW / 2, d.y], [d.x + d.colW / 2, d.y]]);
  return forward ? points : points.reverse();
}
