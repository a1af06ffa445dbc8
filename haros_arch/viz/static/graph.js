// The Computation Graph of one configuration: vertices and edges from the JSON model,
// filters and collapsed namespaces applied, then drawn with D3 (text only, never HTML).

const RESOURCE_OF = {
  'publish': 'topic', 'subscribe': 'topic', 'server': 'service', 'client': 'service',
  'action-server': 'action', 'action-client': 'action',
  'read': 'parameter', 'write': 'parameter', 'declare': 'parameter',
};
// Links that flow from the resource into the node (drawn resource -> node).
const INTO_NODE = new Set(['subscribe', 'server', 'action-server', 'read', 'declare']);
const USERS = {
  topic: ['publishers', 'subscribers'], service: ['servers', 'clients'],
  action: ['servers', 'clients'], parameter: ['readers', 'writers'],
};
const COLLECTIONS = {node: 'nodes', topic: 'topics', service: 'services', action: 'actions', parameter: 'parameters'};
const INFRA = /^(.*\/)?(rosout|rosout_agg|tf|tf_static)$/;
const CHAR_W = 6.7;
const SMALL_W = 6.1;

function entityId(kind, item) {
  return item.id || (kind + ':' + item.name);
}

// Everything about one configuration that does not depend on filters.
// How much of a node instance's interface is known, and why not: the instance's
// completeness (from the JSON model), the reasons from its node model.
const KNOWN_INTERFACE = ['complete', 'model'];
function interfaceOf(item, nodeModels) {
  const model = item.node ? nodeModels.get(item.node) : null;
  const completeness = item.completeness || (item.node ? (model && model.completeness) || 'complete' : 'unknown');
  let reasons = (model && model.completeness_reasons) || [];
  if (!item.node) reasons = ['no source and no interface model for what it runs'];
  return {completeness, reasons, incomplete: !KNOWN_INTERFACE.includes(completeness)};
}

function indexConfiguration(config, nodeModels = new Map()) {
  const entities = new Map();
  for (const kind of Object.keys(COLLECTIONS)) {
    for (const item of config[COLLECTIONS[kind]] || []) {
      const id = entityId(kind, item);
      entities.set(id, {
        id, kind, item, name: String(item.name || ''), group: '', path: [],
        unresolved: String(item.name || '').includes('?'),
        conditional: (item.conditions || []).length > 0,
        links: [],
        ...(kind === 'node' ? {iface: interfaceOf(item, nodeModels)} : {}),
      });
    }
  }
  // Namespace boxes, nested; every entity gets the path of boxes around it.
  const tree = namespaceTree([...entities.values()]);
  for (const e of entities.values()) e.group = e.path.length ? e.path[e.path.length - 1] : '';
  const byName = new Map();
  for (const e of entities.values()) {
    const key = e.kind + ':' + e.name;
    if (!byName.has(key)) byName.set(key, []);
    byName.get(key).push(e);
  }
  const links = [];
  for (const link of config.links || []) {
    const kind = RESOURCE_OF[link.kind];
    if (!kind) continue;
    const node = (byName.get('node:' + link.node) || [])[0];
    const resource = findResource(link, kind, entities, byName);
    if (!node || !resource) continue;
    const entry = {link, node, resource};
    links.push(entry);
    node.links.push(entry);
    resource.links.push(entry);
  }
  return {config, entities, links, tree};
}

function findResource(link, kind, entities, byName) {
  if (link.resource && entities.has(link.resource)) return entities.get(link.resource);
  const same = byName.get(kind + ':' + link.name) || [];
  if (same.length <= 1) return same[0];
  const users = USERS[kind];
  return same.find(e => users.some(field => (e.item[field] || []).includes(link.node))) || same[0];
}

// Vertices and edges after filters and collapsing.
function buildView(index, options) {
  const hidden = e => (
    (options.hideParameters && e.kind === 'parameter') ||
    (options.hideServices && (e.kind === 'service' || e.kind === 'action')) ||
    (options.hideInfra && e.kind !== 'node' && INFRA.test(e.name)) ||
    (options.hideActionWire && e.kind !== 'node' && e.kind !== 'action' && e.links.length > 0 &&
      e.links.every(entry => entry.link.origin === 'action')) ||
    (options.hideSingleEnded && e.kind === 'topic' &&
      (!(e.item.publishers || []).length || !(e.item.subscribers || []).length)));
  const vertices = new Map(), edges = new Map();
  const boxes = index.tree.boxes;
  const vertexFor = e => {
    const shut = e.path.findIndex(name => options.collapsed.has(name));
    if (shut >= 0) {
      const name = e.path[shut], id = 'namespace:' + name;
      if (!vertices.has(id)) {
        const path = e.path.slice(0, shut);
        const v = makeVertex({id, kind: 'namespace', name, group: path.length ? path[path.length - 1] : '', path, members: [], box: boxes.get(name)});
        v.label = boxes.get(name).label;
        vertices.set(id, v);
      }
      return vertices.get(id);
    }
    if (!vertices.has(e.id)) {
      const v = makeVertex(e);
      const base = e.group ? boxes.get(e.group).base : '/';
      if (base !== '/' && v.name.startsWith(base)) v.label = v.name.slice(base.length);
      vertices.set(e.id, v);
    }
    return vertices.get(e.id);
  };
  for (const e of index.entities.values()) {
    if (hidden(e)) continue;
    const v = vertexFor(e);
    if (v.kind === 'namespace') v.entity.members.push(e);
  }
  for (const entry of index.links) {
    if (hidden(entry.node) || hidden(entry.resource)) continue;
    const n = vertexFor(entry.node), r = vertexFor(entry.resource);
    if (n === r) continue;
    const [source, target] = INTO_NODE.has(entry.link.kind) ? [r, n] : [n, r];
    const key = source.id + '\u0000' + target.id;
    if (!edges.has(key)) edges.set(key, {id: key, source, target, kind: entry.link.kind, links: []});
    edges.get(key).links.push(entry);
  }
  for (const edge of edges.values()) {
    edge.conditional = edge.links.every(l => (l.link.conditions || []).length > 0);
    edge.aggregate = edge.source.kind === 'namespace' || edge.target.kind === 'namespace';
  }
  let list = [...vertices.values()];
  if (options.hideDisconnected) {
    const used = new Set();
    for (const edge of edges.values()) { used.add(edge.source); used.add(edge.target); }
    list = list.filter(v => used.has(v));
  }
  for (const v of list) {
    if (v.kind === 'namespace') v.counts = memberCounts(v.entity.members);
  }
  for (const v of list) {
    v.w = Math.max(v.kind === 'parameter' ? 50 : 70, v.label.length * CHAR_W + 28,
      ...(v.counts || []).map(line => line.length * SMALL_W + 28));
  }
  return {vertices: list, edges: [...edges.values()], tree: index.tree, rects: new Map()};
}

function makeVertex(e) {
  return {
    id: e.id, kind: e.kind, name: e.name, group: e.group, path: e.path, entity: e, label: e.name,
    w: 0, h: e.kind === 'parameter' ? 22 : e.kind === 'namespace' ? 56 : 28, x: 0, y: 0,
  };
}

const PLURAL = {node: 'nodes', topic: 'topics', service: 'services', action: 'actions', parameter: 'parameters'};

// What a collapsed namespace holds (as drawn), in two lines: "10 nodes · 34 topics",
// "3 services · 10 parameters".
function memberCounts(members) {
  const n = new Map();
  for (const m of members) n.set(m.kind, (n.get(m.kind) || 0) + 1);
  const say = kinds => kinds.filter(k => n.get(k)).map(k => `${n.get(k)} ${n.get(k) === 1 ? k : PLURAL[k]}`).join(' \u00b7 ');
  return [say(['node', 'topic']), say(['service', 'action', 'parameter'])].filter(Boolean);
}

// ---- drawing -------------------------------------------------------------------------

function shapePath(v) {
  const w = v.w / 2, h = v.h / 2;
  switch (v.kind) {
    case 'service': { const c = 10; return `M${-w},0 L${-w + c},${-h} L${w - c},${-h} L${w},0 L${w - c},${h} L${-w + c},${h} Z`; }
    case 'action': { const c = 7; return `M${-w + c},${-h} L${w - c},${-h} L${w},${-h + c} L${w},${h - c} L${w - c},${h} L${-w + c},${h} L${-w},${h - c} L${-w},${-h + c} Z`; }
    case 'parameter': { const s = 6; return `M${-w + s},${-h} L${w},${-h} L${w - s},${h} L${-w},${h} Z`; }
    case 'topic': return roundedRect(w, h, h);
    case 'namespace': return `M${-w},${-h} L${-w + 28},${-h} L${-w + 34},${-h - 6} L${-w + 60},${-h - 6} L${-w + 64},${-h} L${w},${-h} L${w},${h} L${-w},${h} Z`;
    default: return roundedRect(w, h, 5);
  }
}

function roundedRect(w, h, r) {
  return `M${-w + r},${-h} L${w - r},${-h} A${r},${r} 0 0 1 ${w},${-h + r} L${w},${h - r} ` +
    `A${r},${r} 0 0 1 ${w - r},${h} L${-w + r},${h} A${r},${r} 0 0 1 ${-w},${h - r} ` +
    `L${-w},${-h + r} A${r},${r} 0 0 1 ${-w + r},${-h} Z`;
}

// In the layered layout (e.points set) an edge leaves the side of its source facing its
// target, runs straight to the edge of the source's column, through every column it
// crosses at its dummy's height, and into the target the same way: it only bends in the
// gaps between columns (one smooth cubic per gap, horizontal at both ends), so it never
// runs across a vertex of a column. Without points (force layout, the grid of collapsed
// namespaces) it is one free curve.
function edgePath(e) {
  const s = e.source, t = e.target;
  if (!e.points) return curveThrough(freeEnds(s, t), 30);
  const mid = e.points;
  const firstX = mid.length ? mid[0][0] : t.x, lastX = mid.length ? mid[mid.length - 1][0] : s.x;
  if (!mid.length && Math.abs(t.x - s.x) < 1) {  // same column: round the right side
    const x1 = s.x + s.w / 2, x2 = t.x + t.w / 2 + 4, bulge = Math.max(x1, x2) + 50;
    return `M${x1},${s.y} C${bulge},${s.y} ${bulge},${t.y} ${x2},${t.y}`;
  }
  const out = firstX >= s.x ? 1 : -1, into = t.x >= lastX ? 1 : -1;
  const sw = s.colW || s.w, tw = t.colW || t.w;
  return curveThrough([[s.x + out * s.w / 2, s.y], [s.x + out * Math.max(sw, s.w) / 2, s.y], ...mid,
    [t.x - into * Math.max(tw, t.w) / 2, t.y], [t.x - into * (t.w / 2 + 4), t.y]], 0);
}

function freeEnds(s, t) {
  const forward = t.x >= s.x;
  return [[s.x + (forward ? s.w / 2 : -s.w / 2), s.y], [t.x + (forward ? -t.w / 2 - 4 : t.w / 2 + 4), t.y]];
}

// Cubic segments, horizontal at every point (at least `reach` long handles).
function curveThrough(points, reach) {
  const pts = points.filter((p, i) => i === 0 || Math.abs(p[0] - points[i - 1][0]) + Math.abs(p[1] - points[i - 1][1]) > 0.5);
  let d = `M${pts[0][0]},${pts[0][1]}`;
  for (let i = 1; i < pts.length; i++) {
    const [x1, y1] = pts[i - 1], [x2, y2] = pts[i];
    if (Math.abs(y2 - y1) < 0.5) { d += ` L${x2},${y2}`; continue; }
    const dx = Math.max(reach, Math.abs(x2 - x1) / 2) * (x2 >= x1 ? 1 : -1);
    d += ` C${x1 + dx},${y1} ${x2 - dx},${y2} ${x2},${y2}`;
  }
  return d;
}

function conditionText(conditions) {
  return (conditions || []).map(c => {
    const where = c.location && c.location.file ? ` (${shownFile(c.location.file)}:${c.location.line})` : '';
    return `${c.statement || c.kind || 'if'} ${c.text}${where}`;
  }).join('\n');
}

function vertexTitle(v) {
  if (v.kind === 'namespace') return `${boxTitle(v.entity.box)}: ${v.counts.join(', ')} (click to open)`;
  const item = v.entity.item;
  const lines = [`${v.kind} ${v.name}`];
  if (item.node) lines.push(`runs ${item.node}`);
  if (item.types && item.types.length) lines.push(item.types.join(', '));
  if (item.type) lines.push(String(item.type));
  if (v.entity.unresolved) lines.push('name not known statically (?)');
  if (v.entity.iface && v.entity.iface.incomplete) {
    lines.push(`interface ${v.entity.iface.completeness}: what it publishes, subscribes, serves or reads is not all known`);
    for (const reason of v.entity.iface.reasons.slice(0, 3)) lines.push('  ' + reason);
  }
  const cond = conditionText(item.conditions);
  if (cond) lines.push('only if:\n' + cond);
  return lines.join('\n');
}

const TITLE_LINKS = 12;

function edgeTitle(e) {
  const lines = e.links.slice(0, TITLE_LINKS).map(({link}) => {
    const given = link.given && link.given !== link.name ? ` (given "${link.given}")` : '';
    const cond = conditionText(link.conditions);
    return `${link.node} ${link.kind} ${link.name}${given}` + (link.type ? `\n  ${link.type}` : '') +
      (cond ? '\n  only if: ' + cond.replace(/\n/g, '\n           ') : '');
  });
  if (e.links.length > TITLE_LINKS) lines.push(`\u2026 and ${e.links.length - TITLE_LINKS} more`);
  const head = e.aggregate ? [`${e.links.length} link${e.links.length === 1 ? '' : 's'} from ${e.source.name} to ${e.target.name}`] : [];
  return [...head, ...lines].join('\n');
}

function edgeClass(e) {
  return `edge k-${e.aggregate ? 'aggregate' : e.kind}` + (e.conditional ? ' conditional' : '');
}

function edgeMarker(e) {
  return `url(#arrow-${e.aggregate ? 'aggregate' : RESOURCE_OF[e.kind] || 'topic'})`;
}

// Aggregated edges grow with the number of links they stand for.
function edgeWidth(e) {
  return e.aggregate ? Math.min(6, 1.2 + Math.log2(e.links.length)) : null;
}

function drawGraph(root, view, handlers) {
  root.selectAll('*').remove();
  const groups = root.append('g').attr('class', 'groups');
  const edgeLayer = root.append('g').attr('class', 'edges');
  const vertexLayer = root.append('g').attr('class', 'vertices');

  const edgeSel = edgeLayer.selectAll('path').data(view.edges).join('path')
    .attr('class', edgeClass)
    .attr('data-source', e => e.source.id).attr('data-target', e => e.target.id)
    .attr('marker-end', edgeMarker)
    .style('stroke-width', edgeWidth)
    .attr('d', edgePath);
  edgeSel.append('title').text(edgeTitle);

  const vertexSel = vertexLayer.selectAll('g').data(view.vertices, v => v.id).join('g')
    .attr('class', v => `vertex k-${v.kind}` + (v.entity.unresolved ? ' unresolved' : '') +
      (v.entity.conditional ? ' conditional' : '') +
      (v.entity.iface && v.entity.iface.incomplete ? ' incomplete iface-' + v.entity.iface.completeness : ''))
    .attr('data-id', v => v.id)
    .attr('transform', v => `translate(${v.x},${v.y})`);
  vertexSel.append('path').attr('class', 'shape').attr('d', shapePath);
  vertexSel.append('text').attr('class', 'label').attr('y', v => v.counts ? -v.h / 2 + 16 : 0)
    .attr('dy', '0.35em').text(v => v.label);
  vertexSel.filter(v => v.counts).selectAll('text.counts').data(v => v.counts).join('text')
    .attr('class', 'counts').attr('y', (_, i) => 5 + i * 13).attr('dy', '0.35em').text(line => line);
  vertexSel.filter(v => v.entity.unresolved).append('g').attr('class', 'badge')
    .attr('transform', v => `translate(${v.w / 2 - 2},${-v.h / 2})`)
    .call(g => { g.append('circle').attr('r', 7); g.append('text').attr('dy', '0.35em').text('?'); });
  vertexSel.append('title').text(vertexTitle);

  const incident = new Map(view.vertices.map(v => [v, []]));
  edgeSel.each(function (e) { incident.get(e.source).push(this); incident.get(e.target).push(this); });
  vertexSel.on('click', (event, v) => { event.stopPropagation(); handlers.click(v); })
    .call(d3.drag().clickDistance(4).on('drag', function (event, v) {
      v.x = event.x; v.y = event.y;
      d3.select(this).attr('transform', `translate(${v.x},${v.y})`);
      d3.selectAll(incident.get(v)).attr('d', edgePath);
      drawGroups(groups, view, handlers);
    }));
  drawGroups(groups, view, handlers);
  return {
    vertexSel, edgeSel,
    update() {
      vertexSel.attr('transform', v => `translate(${v.x},${v.y})`);
      edgeSel.attr('d', edgePath);
      drawGroups(groups, view, handlers);
    },
  };
}

// A light box behind each open namespace, around its members and the boxes inside it,
// labelled; clicking the label collapses it. The layered layout leaves room for the boxes
// (view.rects); after a drag, or in the force layout, they grow to hold what they hold.
const BOX_PAD = 14;
const BOX_TOP = 26;

function groupRects(view) {
  const rects = new Map();
  const grow = (name, x0, y0, x1, y1) => {
    const r = rects.get(name);
    if (!r) rects.set(name, {x0, y0, x1, y1});
    else { r.x0 = Math.min(r.x0, x0); r.y0 = Math.min(r.y0, y0); r.x1 = Math.max(r.x1, x1); r.y1 = Math.max(r.y1, y1); }
  };
  for (const [name, r] of view.rects || []) grow(name, r.x0, r.y0, r.x1, r.y1);
  for (const v of view.vertices) {
    if (v.group) grow(v.group, v.x - v.w / 2 - BOX_PAD, v.y - v.h / 2 - BOX_TOP, v.x + v.w / 2 + BOX_PAD, v.y + v.h / 2 + BOX_PAD);
  }
  const names = [...rects.keys()].sort((a, b) => view.tree.boxes.get(b).depth - view.tree.boxes.get(a).depth);
  for (const name of names) {
    const up = view.tree.boxes.get(name).path;
    const r = rects.get(name);
    if (up.length) grow(up[up.length - 1], r.x0 - BOX_PAD, r.y0 - BOX_TOP, r.x1 + BOX_PAD, r.y1 + BOX_PAD);
  }
  return rects;
}

function drawGroups(layer, view, handlers) {
  const rects = groupRects(view);
  const data = [...rects].map(([name, r]) => ({name, box: view.tree.boxes.get(name), ...r}))
    .sort((a, b) => a.box.depth - b.box.depth);
  const sel = layer.selectAll('g.group').data(data, b => b.name).join(enter => {
    const g = enter.append('g').attr('class', 'group');
    g.append('rect').attr('rx', 10);
    const label = g.append('text').attr('class', 'group-label');
    label.append('tspan');
    label.append('title');
    return g;
  });
  sel.order();
  sel.attr('data-group', b => b.name).attr('class', b => 'group depth-' + Math.min(b.box.depth, 4));
  sel.select('rect').attr('x', b => b.x0).attr('y', b => b.y0)
    .attr('width', b => b.x1 - b.x0).attr('height', b => b.y1 - b.y0);
  sel.select('text').attr('x', b => b.x0 + 8).attr('y', b => b.y0 + 16)
    .on('click', (event, b) => { event.stopPropagation(); handlers.collapse(b.name); });
  sel.select('text tspan').text(b => `${b.box.label}  \u2212 collapse`);
  sel.select('text title').text(b => boxTitle(b.box) + ' (click to collapse)');
}

function boxTitle(box) {
  if (box.unresolved) return 'names whose namespace is not known';
  return box.prefix ? `names starting with ${box.name.slice(0, -1)}` : `namespace ${box.name}`;
}
