// The Launch view: each configuration's launch tree (model/launch_tree.py) as nested boxes:
// files, then groups, then node rows. All text goes through el() (textContent).

const LAUNCH_MAX_ITEMS = 5000;  // rows drawn at most; the rest are counted

function launchView(config, app) {
  const trees = config.launch_tree || [];
  if (!trees.length) {
    return [el('p', {class: 'muted'}, 'This configuration has no launch tree (a model saved before it was recorded, ' +
      'or no launch file).')];
  }
  const budget = {left: LAUNCH_MAX_ITEMS};
  app.launchNodes = launchNodeMatcher(config);
  const boxes = trees.map(item => launchItem(item, app, budget));
  if (budget.left < 0) boxes.push(el('p', {class: 'muted'}, `${-budget.left} more items not drawn`));
  return boxes;
}

// One item and, iteratively, what it holds (a stack, not recursion: depth is bounded but large).
function launchItem(root, app, budget) {
  const top = launchBox(root, app);
  const stack = [[root, top]];
  while (stack.length) {
    const [item, box] = stack.pop();
    const holder = box.querySelector(':scope > .lt-children') || box;
    for (const child of item.children || []) {
      if (--budget.left < 0) break;
      const made = launchBox(child, app);
      holder.append(made);
      if ((child.children || []).length) stack.push([child, made]);
    }
  }
  return top;
}

// The node instances of the graph that a started node row made: the one of the same name,
// else those launched at the same line (a name the launch file does not give, "/?" in the
// tree, that the node's code sets; one executable may make several nodes). None for a
// part left out.
function launchNodeMatcher(config) {
  const byName = new Map(), byLine = new Map();
  for (const node of config.nodes || []) {
    byName.set(node.name, node);
    const loc = node.location || {};
    if (!loc.file) continue;
    const key = loc.file + ':' + loc.line;
    if (!byLine.has(key)) byLine.set(key, []);
    byLine.get(key).push(node);
  }
  return item => {
    if (item.skipped) return [];
    if (byName.has(item.name)) return [byName.get(item.name)];
    const loc = item.location || {};
    const there = byLine.get(loc.file + ':' + loc.line) || [];
    const same = there.filter(n => !item.detail || n.node === item.detail);
    return same.length ? same : there;
  };
}

function launchValue(value) {
  return value === null || value === undefined ? '(unset)' : value === '' ? '""' : value;
}

function launchConditionText(c) {
  const values = Object.entries(c.values || {}).map(([k, v]) => `${k}=${v === null || v === undefined ? '?' : v}`);
  const state = c.holds === true ? 'holds' : c.holds === false ? 'false' : 'unknown';
  return `${c.statement || 'if'} ${c.text}` + (values.length ? `  (${values.join(', ')})` : '') + ` \u2014 ${state}`;
}

// A node row's remaps: each name in the node's code that a remap changed, drawn from that
// name to the name it resolves to (the graph's "remapped" of its instances); the rules as the
// launch file wrote them are the tooltip. Without code (or when no rule changed a name the
// code uses), the rules as written.
function launchNodeRemaps(item, nodes) {
  const rules = item.remaps || [];
  const seen = new Set(), changed = [];
  for (const node of nodes) {
    for (const [given, before, full] of node.remapped || []) {
      const key = given + '\u0000' + full;
      if (!seen.has(key)) { seen.add(key); changed.push([given, before, full]); }
    }
  }
  const written = rules.map(([a, b]) => `${a} \u2192 ${b}`).join(', ');
  if (changed.length) {
    return el('div', {class: 'lt-remaps', title: written ? `remaps as written: ${written}` : null},
      changed.map(([given, before, full]) => el('div', {class: 'lt-remap lt-remap-code', title: `${given} resolves to ${before}, remapped to ${full}`},
        el('code', {class: 'lt-code-name'}, given), ' \u2192 ', el('code', {class: 'lt-resolved-name'}, full),
        el('span', {class: 'muted'}, ' (name in code \u2192 resolved)'))));
  }
  if (!rules.length) return null;
  return el('div', {class: 'lt-remaps'}, el('span', {class: 'muted'}, 'remaps as written:'),
    rules.map(([a, b]) => el('div', {class: 'lt-remap'}, el('code', {}, a), ' \u2192 ', el('code', {}, b))));
}

function launchBox(item, app) {
  const kind = ['file', 'group', 'node', 'include'].includes(item.kind) ? item.kind : 'file';
  const c = item.condition;
  const classes = ['lt', 'lt-' + kind];
  if (item.skipped) classes.push('skipped');
  if (c) classes.push('conditional', 'cond-' + (c.holds === true ? 'holds' : c.holds === false ? 'false' : 'unknown'));
  const loc = item.location || {};
  const parts = [];
  if (kind === 'node') {
    const nodes = app.launchNodes ? app.launchNodes(item) : [];
    const node = nodes[0] || null;
    const row = el('div', {class: classes.join(' '), 'data-id': node ? node.id : null, 'data-kind': 'node', 'data-name': item.name},
      el('span', {class: 'lt-name'}, nodes.length ? nodes.map(n => n.name).join(', ') : item.name),
      node && (nodes.length > 1 || node.name !== item.name) ? el('span', {class: 'muted'}, `(launch file: ${item.name}) `) : null,
      el('span', {class: 'lt-detail muted'}, item.detail || ''),
      item.skipped ? el('span', {class: 'lt-tag'}, 'not started') : null,
      c ? el('div', {class: 'lt-cond'}, launchConditionText(c)) : null,
      launchNodeRemaps(item, nodes));
    row.__ids = nodes.map(n => n.id);
    row.addEventListener('click', event => { event.stopPropagation(); app.chooseLaunchItem(item, row, node); });
    return row;
  }
  if (kind === 'file') {
    parts.push(el('div', {class: 'lt-head'}, el('span', {class: 'lt-kind'}, 'file'), ' ', el('span', {class: 'lt-name'}, item.name),
      loc.line ? el('span', {class: 'lt-where muted'}, ` included at ${where(loc)}`) : null));
  } else if (kind === 'group') {
    parts.push(el('div', {class: 'lt-head'}, el('span', {class: 'lt-kind'}, 'group'), ' ',
      el('span', {class: 'lt-name'}, item.namespace || item.name || '/'),
      (item.pushed || []).length ? el('span', {class: 'muted'}, ` pushes ${item.pushed.join(', ')}`) : null));
  } else {
    parts.push(el('div', {class: 'lt-head'}, el('span', {class: 'lt-kind'}, 'include'), ' ', el('span', {class: 'lt-name'}, item.name),
      el('span', {class: 'muted'}, ' (not followed)')));
  }
  if (item.skipped) parts.push(el('span', {class: 'lt-tag'}, 'left out'));
  if (c) parts.push(el('div', {class: 'lt-cond'}, launchConditionText(c)));
  if ((item.args || []).length) {
    parts.push(el('div', {class: 'lt-args'}, item.args.map(a => el('div', {class: 'lt-arg', 'data-arg': a.name},
      el('code', {}, a.name), ' = ', el('code', {}, launchValue(a.value)),
      el('span', {class: 'muted'}, ` ${a.origin || ''}`)))));
  }
  if ((item.remaps || []).length) {
    parts.push(el('div', {class: 'lt-remaps'}, item.remaps.map(([a, b]) =>
      el('div', {class: 'lt-remap'}, el('code', {}, a), ' \u2192 ', el('code', {}, b)))));
  }
  parts.push(el('div', {class: 'lt-children'}));
  const box = el('div', {class: classes.join(' '), 'data-kind': kind, 'data-name': item.name}, parts);
  box.addEventListener('click', event => { event.stopPropagation(); app.chooseLaunchItem(item, box); });
  return box;
}

// Where to show a launch item's own lines: a file's include site and its first written line
// (an argument or a child in that file, whose lines the report embeds).
function launchItemPanel(item, app) {
  const loc = item.location || {};
  const parts = [el('div', {class: 'panel-kind'}, 'launch ' + item.kind), el('h2', {class: 'panel-title'}, item.name)];
  if (item.detail) parts.push(field('runs', item.detail));
  if (item.namespace) parts.push(field('namespace', item.namespace));
  if (item.condition) parts.push(field('condition', launchConditionText(item.condition)));
  if (item.skipped) parts.push(el('p', {class: 'warn'}, 'Left out by its condition: not started in this configuration.'));
  if ((item.args || []).length) {
    parts.push(el('h4', {}, 'Arguments'), ...item.args.map(a => el('div', {class: 'lt-panel-arg'},
      el('code', {}, a.name), ' = ', el('code', {}, launchValue(a.value)),
      el('span', {class: 'muted'}, ` ${a.origin || '?'}` + (a.location && a.location.file ? ` at ${where(a.location)}` : '')))));
  }
  if (item.kind === 'file') {
    if (loc.line) parts.push(el('h4', {}, 'Included at'), codeBlock(loc, app.sources));
    const inFile = [...(item.args || []), ...(item.children || [])].map(x => x.location)
      .filter(l => l && l.file === item.name && l.line).sort((a, b) => a.line - b.line);
    if (inFile.length) parts.push(el('h4', {}, 'In the file'), codeBlock(inFile[0], app.sources, 4));
  } else if (loc.line) {
    parts.push(el('h4', {}, 'Written at'), codeBlock(loc, app.sources));
  }
  return parts;
}

function markLaunchSelection(container, id) {
  for (const row of container.querySelectorAll('.lt.chosen')) row.classList.remove('chosen');
  if (!id) return null;
  const row = [...container.querySelectorAll('.lt-node')].find(r => (r.__ids || []).includes(id));
  if (row) row.classList.add('chosen');
  return row || null;
}
