// Side panel, findings and diagnostics lists, and the package view. Every piece of model
// text goes through textContent (el() below); nothing is ever parsed as HTML.

function el(tag, attrs, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs || {})) {
    if (value === undefined || value === null || value === false) continue;
    if (key === 'onclick') node.addEventListener('click', value);
    else if (key === 'class') node.className = value;
    else node.setAttribute(key, String(value));
  }
  for (const child of children.flat()) {
    if (child === undefined || child === null || child === false) continue;
    node.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return node;
}

// Text that may wrap after each '/' or '_' (a long name, type or path breaks between its
// parts, not inside a word, and a table of them fits its column).
function wrappable(text) {
  const parts = String(text).split(/(?<=[\/_])/);
  return parts.flatMap((part, i) => i < parts.length - 1 ? [part, el('wbr')] : [part]);
}

const SEVERITIES = ['error', 'warning', 'info'];

// A file of a workspace folder after the first is named in the model by its absolute
// path; it is shown as that folder's label and its path below it.
function shownFile(file) {
  for (const [folder, label] of DATA.folders || []) {
    if (file.startsWith(folder + '/')) return label + file.slice(folder.length);
  }
  return file;
}

function where(loc) {
  if (!loc || !loc.file) return '';
  return shownFile(loc.file) + (loc.line ? ':' + loc.line + (loc.column ? ':' + loc.column : '') : '');
}

// The lines around a location, from the snippets embedded in the report.
function codeBlock(loc, sources, context = 3) {
  if (!loc || !loc.file) return null;
  const lines = sources[loc.file] || {};
  const rows = [];
  for (let n = Math.max(1, loc.line - context); n <= loc.line + context; n++) {
    if (!(String(n) in lines)) continue;
    rows.push(el('div', {class: 'code-line' + (n === loc.line ? ' at' : '')},
      el('span', {class: 'ln'}, String(n)), el('span', {class: 'src'}, lines[String(n)])));
  }
  return el('div', {class: 'code'},
    el('div', {class: 'code-where'}, where(loc)),
    rows.length ? el('div', {class: 'code-lines'}, rows) : el('div', {class: 'muted'}, 'source not embedded'));
}

function field(label, ...value) {
  return el('div', {class: 'field'}, el('span', {class: 'field-label'}, label), el('span', {class: 'field-value'}, ...value));
}

function conditionList(conditions, sources) {
  if (!conditions || !conditions.length) return null;
  return el('div', {class: 'conditions'}, el('h4', {}, 'Exists only if'),
    conditions.map(c => el('div', {class: 'condition'},
      el('code', {}, `${c.statement || c.kind} ${c.text}`),
      el('span', {class: 'muted'}, ` ${c.kind} condition`),
      codeBlock(c.location, sources, 1))));
}

function severityBadge(severity) {
  return el('span', {class: 'sev sev-' + severity}, severity);
}

// ---- details of one entity -------------------------------------------------------------

const LINK_LABELS = {
  'publish': 'publishes', 'subscribe': 'subscribes to', 'server': 'provides', 'client': 'calls',
  'action-server': 'serves action', 'action-client': 'uses action', 'read': 'reads', 'write': 'sets', 'declare': 'declares',
};

function entityPanel(entity, app) {
  const item = entity.item, sources = app.sources;
  const parts = [el('div', {class: 'panel-kind k-' + entity.kind}, entity.kind === 'node' ? 'node instance' : entity.kind),
    el('h2', {class: 'panel-title'}, entity.name)];
  if (entity.unresolved) {
    parts.push(el('p', {class: 'warn'}, 'Part of this name cannot be known statically (?).'));
    const candidates = (item.candidates || []).map(id => app.index.entities.get(id)).filter(Boolean);
    parts.push(el('div', {class: 'candidates'}, el('h4', {}, 'Candidates'),
      candidates.length ? candidates.map(c => entityLink(c, app)) : el('div', {class: 'muted'}, 'none listed')));
  }
  if (entity.kind === 'node') {
    parts.push(field('runs', item.node || '? (not found in the workspace)'));
    if (entity.iface && entity.iface.incomplete) {
      parts.push(field('interface', entity.iface.completeness));
      parts.push(el('p', {class: 'warn'}, 'Not all of what this node publishes, subscribes, serves or reads is known, ' +
        'so checks that say something is missing do not decide where it could be the missing side.'));
      for (const reason of entity.iface.reasons.slice(0, 5)) parts.push(el('div', {class: 'muted reason'}, reason));
    }
    parts.push(field('namespace', item.namespace || '/'));
    if (item.args) parts.push(field('args', item.args));
    if ((item.remaps || []).length) {
      parts.push(field('remaps', el('span', {}, item.remaps.map(([a, b]) => el('div', {}, el('code', {}, a), ' \u2192 ', el('code', {}, b))))));
    }
  } else {
    const types = item.types || (item.type ? [item.type] : []);
    parts.push(field('type', types.length ? types.join(', ') : '?'));
    if (entity.kind === 'parameter') parts.push(field('value', item.value === null || item.value === undefined ? 'unknown' : JSON.stringify(item.value)));
    if (types.length > 1) parts.push(el('p', {class: 'warn'}, 'Used with more than one type.'));
  }
  parts.push(conditionList(item.conditions, sources));
  if (item.location && item.location.file) {
    parts.push(el('h4', {}, entity.kind === 'node' ? 'Launched at' : 'Set at'), codeBlock(item.location, sources));
  }
  const found = app.findingsFor(entity.id);
  if (found.length) parts.push(el('h4', {}, `Findings (${found.length})`), el('div', {class: 'finding-list'}, found.map(f => findingItem(f, app))));
  parts.push(el('h4', {}, `Links (${entity.links.length})`));
  if (entity.kind === 'parameter' && (item.writers || []).includes('<launch>')) {
    parts.push(el('div', {class: 'link'}, el('span', {class: 'muted'}, 'set by the launch file')));
  }
  for (const entry of entity.links) parts.push(linkBlock(entry, entity, app));
  return parts;
}

function linkBlock(entry, entity, app) {
  const link = entry.link;
  const other = entity.kind === 'node' ? entry.resource : entry.node;
  const rows = [
    el('div', {class: 'link-head'},
      entity.kind === 'node' ? [LINK_LABELS[link.kind] || link.kind, ' ', entityLink(other, app)]
        : [entityLink(other, app), ' ', LINK_LABELS[link.kind] || link.kind]),
  ];
  const given = link.given && link.given !== link.name ? link.given : null;
  rows.push(field('name', el('code', {}, link.name), given ? el('span', {class: 'muted'}, ` (given "${given}")`) : null));
  if (link.type) rows.push(field('type', link.type));
  if (link.queue_size !== null && link.queue_size !== undefined) rows.push(field('queue size', String(link.queue_size)));
  if (link.qos) rows.push(field('QoS', Object.entries(link.qos).map(([k, v]) => `${k}=${v}`).join(', ')));
  if (link.latch) rows.push(field('latched', 'yes'));
  rows.push(conditionList(link.conditions, app.sources));
  rows.push(codeBlock(link.location, app.sources));
  return el('div', {class: 'link k-' + link.kind}, rows);
}

function entityLink(entity, app) {
  return el('a', {class: 'entity-link k-' + entity.kind, href: '#', 'data-id': entity.id,
    onclick: event => { event.preventDefault(); app.select(entity.id, true); }}, entity.name);
}

// ---- findings and diagnostics --------------------------------------------------------

function shorten(text, most) {
  return text.length <= most ? text : text.slice(0, most - 1) + '\u2026';
}

function findingItem(finding, app) {
  // each name once: the instances of one duplicated name are one name
  const names = [...new Set((finding.entities || []).map(id => (app.index.entities.get(id) || {name: id}).name))];
  const item = el('div', {class: 'item finding', 'data-rule': finding.rule, onclick: () => app.showFinding(finding)},
    severityBadge(finding.severity),
    el('span', {class: 'item-title'}, names.length ? names.slice(0, 2).join(' \u00b7 ') : (finding.title || finding.rule)),
    el('span', {class: 'item-sub'}, shorten(finding.message || finding.rule, 160)));
  item.__finding = finding;
  return item;
}

function findingPanel(finding, app) {
  const involved = (finding.entities || []).map(id => app.index.entities.get(id) || {id, name: id, kind: 'missing'});
  return [
    el('div', {class: 'panel-kind'}, 'finding'),
    el('h2', {class: 'panel-title'}, finding.title || finding.rule),
    field('rule', finding.rule), field('severity', severityBadge(finding.severity)),
    finding.configuration ? field('configurations', (finding.configurations || [finding.configuration]).join(', ')) : null,
    el('p', {class: 'message'}, finding.message || ''),
    el('h4', {}, `Involves (${involved.length})`),
    el('div', {}, involved.map(e => el('div', {}, e.kind === 'missing' ? el('code', {}, e.id) : entityLink(e, app)))),
    codeBlock(finding.location, app.sources),
    ...((finding.also || []).length ? [el('h4', {}, `The same problem at (${finding.also.length})`),
      ...finding.also.map(loc => codeBlock(loc, app.sources, 1))] : []),
  ];
}

function diagnosticItem(d, app) {
  return el('div', {class: 'item diagnostic', 'data-code': d.code, onclick: () => app.showPanel([
    el('div', {class: 'panel-kind'}, 'diagnostic'), el('h2', {class: 'panel-title'}, d.code),
    field('severity', severityBadge(d.severity)), el('p', {class: 'message'}, d.message),
    codeBlock(d.location, app.sources),
    // said once for several places (an unset launch argument's other uses)
    ...((d.also || []).length ? [el('h4', {}, `The same problem at (${d.also.length})`),
      ...d.also.map(loc => codeBlock(loc, app.sources, 1))] : [])])},
  severityBadge(d.severity), el('span', {class: 'item-title'}, d.message), el('span', {class: 'item-sub'}, where(d.location)));
}

function bySeverity(items) {
  return items.slice().sort((a, b) => SEVERITIES.indexOf(a.severity) - SEVERITIES.indexOf(b.severity));
}

// ---- the package view ----------------------------------------------------------------

function packageView(model, app) {
  const instances = new Map();
  for (const e of app.index.entities.values()) {
    if (e.kind === 'node' && e.item.node) {
      if (!instances.has(e.item.node)) instances.set(e.item.node, []);
      instances.get(e.item.node).push(e);
    }
  }
  return (model.packages || []).map(pkg => el('section', {class: 'package'},
    el('h2', {}, pkg.name, el('span', {class: 'muted'}, `  ${pkg.build_type || ''}  ${pkg.path || ''}`)),
    (pkg.nodes || []).length ? pkg.nodes.map(node => {
      const name = node.name || `${node.package}/${node.executable}`;
      const running = instances.get(name) || [];
      return el('div', {class: 'pkg-node'},
        el('h3', {}, name, el('span', {class: 'muted'}, `  ${node.kind || ''} \u00b7 ${node.language || ''}`)),
        field('sources', (node.sources || []).join(', ') || '?'),
        field('instances', running.length ? running.map(e => entityLink(e, app)) : el('span', {class: 'muted'}, 'not launched in this configuration')),
        el('table', {class: 'calls'},
          el('tr', {}, el('th', {}, 'interface'), el('th', {}, 'name'), el('th', {}, 'type'), el('th', {}, 'where')),
          (node.calls || []).map(call => el('tr', {class: (call.conditions || []).length ? 'conditional' : ''},
            // a name roscpp resolves for the code, a command-line word it reads: no parameter
            el('td', {}, call.resolved ? 'resolves' : call.argument ? 'argument' : call.kind),
            el('td', {}, el('code', {}, wrappable(call.name))),
            el('td', {}, call.resolved ? '' : wrappable(call.type || '?')),
            el('td', {}, el('a', {href: '#', onclick: event => {
              event.preventDefault();
              app.showPanel([el('div', {class: 'panel-kind'}, call.kind + ' call'), el('h2', {class: 'panel-title'}, call.name),
                field('node', name), field('type', call.type || '?'), conditionList(call.conditions, app.sources),
                codeBlock(call.location, app.sources)]);
            }}, wrappable(where(call.location))))))));
    }) : el('p', {class: 'muted'}, 'no nodes found in this package')));
}
