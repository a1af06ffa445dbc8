// The namespace boxes of one configuration, nested.
//
// Namespaces are those of node instances and their ancestors; every element sits in the
// deepest one its name is in (a node in its namespace, a topic or parameter in the
// namespace it is named under, so a node's private names sit beside it). A namespace
// that holds more than one element (elements or namespaces that hold something) is a
// box; one that holds a single namespace is merged with it (/robot1/ holding only
// /robot1/sensors/ is one box, /robot1/sensors/); one that holds a single element gives
// it to its parent. A box (or /) that directly holds more than PREFIX_AT elements groups
// them by the first word of their names (camera_driver, camera_info, /camera/image ->
// "/camera*") when a word is shared by PREFIX_MIN or more, two of them nodes (one node
// and its private names are not a group), so a flat 300-node system opens
// as boxes of related names instead of one wall. What is still more than PREFIX_AT there
// (global topics and services in namespaces no node is in: /api/..., /vehicle/status/...)
// goes into a box of each namespace that names PREFIX_MIN or more of them, and names
// whose namespace is not known (a topic named '?', '/?/scan') into one box of unresolved
// names, so that Autoware opens as boxes, not as a column of a hundred global names.
//
// box: {name (a namespace, '/robot1/arm/', a name prefix, '/camera*', or base + '?/' for
// the unresolved names), label (relative
// to the enclosing box), base (what member labels are relative to), parent, depth,
// children, members (direct), size (elements in the subtree)}. entity.path: the names of
// the boxes around it, outermost first.

const PREFIX_AT = 40;
const PREFIX_MIN = 3;
const PARAM_BOX = 8;

function namespaceTree(entities) {
  const spaces = new Set();
  for (const e of entities) {
    if (e.kind !== 'node') continue;
    for (const ns of ancestors(e.item.namespace || '/')) spaces.add(ns);
  }
  // A namespace holding PARAM_BOX parameters or more (a node's private ones, a rosparam
  // file's sections) is a box of its own, collapsed at first.
  const params = new Map();
  for (const e of entities) {
    if (e.kind === 'parameter') for (const ns of ancestors(parentOf(e.name))) params.set(ns, (params.get(ns) || 0) + 1);
  }
  const paramSpaces = new Set([...params].filter(([ns, n]) => n >= PARAM_BOX && !spaces.has(ns)).map(([ns]) => ns));
  for (const ns of paramSpaces) for (const up of ancestors(ns)) spaces.add(up);
  const home = new Map();  // namespace -> direct entities
  const deepest = e => {
    const parts = e.kind === 'node' ? ancestors(e.item.namespace || '/') : ancestors(parentOf(e.name));
    for (let i = parts.length - 1; i >= 0; i--) if (spaces.has(parts[i])) return parts[i];
    return '/';
  };
  for (const e of entities) {
    const ns = deepest(e);
    if (!home.has(ns)) home.set(ns, []);
    home.get(ns).push(e);
  }
  const kids = new Map();
  for (const ns of spaces) {
    const up = parentOf(ns.slice(0, -1));
    if (!kids.has(up)) kids.set(up, []);
    kids.get(up).push(ns);
  }
  // What a namespace gives its parent: a box, a single entity, or nothing.
  const boxes = new Map();
  const build = ns => {
    const inner = (kids.get(ns) || []).map(build).filter(Boolean);
    const direct = home.get(ns) || [];
    const elements = inner.length + direct.length;
    if (ns !== '/' && elements === 1) return inner[0] || {entity: direct[0]};
    if (ns !== '/' && elements === 0) return null;
    const box = {name: ns, base: ns, members: [], children: [], parent: null, params: paramSpaces.has(ns)};
    for (const piece of inner) {
      if (piece.entity) box.members.push(piece.entity);
      else { box.children.push(piece); piece.parent = box; }
    }
    box.members.push(...direct);
    return box;
  };
  const root = build('/');
  root.name = '';
  root.base = '/';
  groupByPrefix(root);
  const visit = (box, path, depth) => {
    box.depth = depth;
    box.path = path;
    if (box.name) boxes.set(box.name, box);
    const here = box.name ? [...path, box.name] : path;
    for (const e of box.members) e.path = here;
    box.size = box.members.length;
    for (const child of box.children) {
      child.label = child.unresolved ? '? unresolved names'
        : child.name.startsWith(box.base) && box.name ? child.name.slice(box.base.length) : child.name;
      visit(child, here, depth + 1);
      box.size += child.size;
    }
  };
  visit(root, [], 0);
  return {root, boxes};
}

// Boxes (and /) with too many direct members: members sharing the first word of their
// name (relative to the box) go into a box of their own.
function groupByPrefix(box) {
  for (const child of box.children) groupByPrefix(child);
  if (box.members.length <= PREFIX_AT) return;
  const grouped = new Set();
  for (const [word, members] of bucket(box.members, e => firstWord(e.name, box.base))) {
    const nodes = members.filter(e => e.kind === 'node').length;
    if (members.length < PREFIX_MIN || nodes < 2 || members.length === box.members.length) continue;
    const name = box.base + word + '*';
    box.children.push({name, base: box.base, members, children: [], parent: box, prefix: true});
    for (const e of members) grouped.add(e);
  }
  box.members = box.members.filter(e => !grouped.has(e));
  groupByNamespace(box);
}

// What is still crowded in a box after the first words: names (no node: a node's place is
// its namespace) under the same first namespace below the box, and names with '?' before
// their last part.
function groupByNamespace(box) {
  if (box.members.length <= PREFIX_AT) return;
  const grouped = new Set();
  const spaceOf = e => (e.kind === 'node' ? '' : firstSpace(e.name, box.base));
  for (const [ns, members] of bucket(box.members, spaceOf)) {
    if (members.length < PREFIX_MIN || members.length === box.members.length) continue;
    const name = box.base + ns;
    const unresolved = ns === '?/';
    let child = box.children.find(c => c.name === name);
    if (child) child.members.push(...members);
    else {
      child = {name, base: unresolved ? box.base : name, members, children: [], parent: box, unresolved};
      box.children.push(child);
    }
    for (const e of members) grouped.add(e);
    if (!unresolved) groupByNamespace(child);
  }
  box.members = box.members.filter(e => !grouped.has(e));
}

// The first namespace of a name below base ('/api/' of '/api/routing/state' below '/'),
// '?/' for a name whose namespace is not known there, '' for a name right in base.
function firstSpace(name, base) {
  if (!name.startsWith(base)) return name.includes('?') ? '?/' : '';
  const rest = name.slice(base.length);
  const cut = rest.indexOf('/');
  const first = cut < 0 ? rest : rest.slice(0, cut + 1);
  if (first.includes('?')) return '?/';
  return cut < 0 ? '' : first;
}

// The members by key (those whose key is '' left out), in order of first appearance.
function bucket(members, keyOf) {
  const found = new Map();
  for (const e of members) {
    const key = keyOf(e);
    if (!key) continue;
    if (!found.has(key)) found.set(key, []);
    found.get(key).push(e);
  }
  return found;
}

function firstWord(name, base) {
  const rest = name.startsWith(base) ? name.slice(base.length) : name.replace(/^\//, '');
  const match = /^[A-Za-z0-9]+/.exec(rest);
  return match ? match[0] : '';
}

// '/a/b/' -> ['/a/', '/a/b/']; names with '?' stop before the unknown part.
function ancestors(ns) {
  const out = [];
  let acc = '/';
  for (const part of String(ns).split('/').filter(Boolean)) {
    if (part.includes('?')) break;
    acc += part + '/';
    out.push(acc);
  }
  return out;
}

function parentOf(name) {
  const text = String(name || '');
  const cut = text.lastIndexOf('/');
  return cut <= 0 ? '/' : text.slice(0, cut + 1);
}
