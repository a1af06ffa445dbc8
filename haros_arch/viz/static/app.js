// The report application: page skeleton, state, controls. Runs after d3 and the other
// modules of this folder (concatenated into one inline script by haros_arch/viz/html.py).

const started = performance.now();
const DATA = JSON.parse(document.getElementById('haros-data').textContent);
const MODEL = DATA.model || {};
const CONFIGS = MODEL.configurations || [];

// Above this many vertices (after filters) a configuration opens with its namespaces
// collapsed into boxes.
const BIG = 60;
const READABLE = 0.6;  // the least zoom an opened namespace is shown at

const app = {
  sources: DATA.sources || {},
  findings: DATA.findings || [],
  index: null, view: null, drawn: null, sim: null, selected: null,
  options: {hideParameters: false, hideServices: false, hideInfra: true, hideActionWire: true,
            hideSingleEnded: false, hideDisconnected: false, collapsed: new Set()},
  layout: 'layered',
};

// ---- skeleton --------------------------------------------------------------------------

const ui = {};
function skeleton() {
  ui.config = el('select', {id: 'config', 'aria-label': 'configuration'},
    CONFIGS.map((c, i) => el('option', {value: String(i)}, c.name)));
  ui.search = el('input', {id: 'search', type: 'search', placeholder: 'search names\u2026  (Enter: go)', 'aria-label': 'search'});
  ui.layout = el('select', {id: 'layout', 'aria-label': 'layout'},
    el('option', {value: 'layered'}, 'layered layout'), el('option', {value: 'force'}, 'force layout'));
  ui.tabGraph = el('button', {class: 'tab active', id: 'tab-graph'}, 'Graph');
  ui.tabPackages = el('button', {class: 'tab', id: 'tab-packages'}, 'Packages');
  ui.tabLaunch = el('button', {class: 'tab', id: 'tab-launch'}, 'Launch');
  ui.fit = el('button', {id: 'fit', title: 'fit the graph to the window'}, 'Fit');
  const header = el('header', {id: 'top'},
    el('h1', {}, el('span', {class: 'logo'}, 'haros-arch'), ' ', MODEL.project || ''),
    el('label', {class: 'control'}, 'configuration ', ui.config),
    el('div', {class: 'tabs'}, ui.tabGraph, ui.tabPackages, ui.tabLaunch),
    ui.search, ui.layout, ui.fit);

  ui.filters = el('section', {id: 'filters'}, el('h3', {}, 'Show'),
    [['hideParameters', 'parameters'], ['hideServices', 'services and actions'], ['hideInfra', 'rosout and tf'],
     ['hideActionWire', 'the topics and services inside actions'],
     ['hideSingleEnded', 'topics missing a publisher or subscriber'], ['hideDisconnected', 'unconnected elements']]
      .map(([key, label]) => {
        const box = el('input', {type: 'checkbox', 'data-filter': key});
        box.checked = !app.options[key];
        box.addEventListener('change', () => { app.options[key] = !box.checked; renderGraph(); });
        return el('label', {class: 'check'}, box, ' ' + label);
      }));
  ui.namespaces = el('section', {id: 'namespaces'});
  ui.findings = el('section', {id: 'findings'});
  ui.diagnostics = el('section', {id: 'diagnostics'});
  ui.live = el('section', {id: 'live', hidden: true});
  const side = el('aside', {id: 'side'}, ui.findings, ui.live, ui.filters, ui.namespaces, ui.diagnostics);

  ui.svg = d3.select(el('div')).append('svg').attr('id', 'graph');
  const defs = ui.svg.append('defs');
  // Each arrowhead also in a dimmed variant, which report.css puts on dimmed edges.
  for (const kind of ['topic', 'service', 'action', 'parameter', 'aggregate']) {
    for (const dim of ['', '-dim']) {
      const marker = defs.append('marker').attr('id', 'arrow-' + kind + dim)
        .attr('class', 'arrow k-' + kind + (dim ? ' dim' : ''))
        .attr('viewBox', '0 -5 10 10').attr('refX', 9).attr('refY', 0).attr('orient', 'auto');
      if (kind === 'aggregate') marker.attr('markerUnits', 'userSpaceOnUse').attr('markerWidth', 12).attr('markerHeight', 12);
      else marker.attr('markerWidth', 7).attr('markerHeight', 7);
      marker.append('path').attr('d', 'M0,-5L10,0L0,5Z');
    }
  }
  ui.viewport = ui.svg.append('g').attr('class', 'viewport');
  ui.zoom = d3.zoom().scaleExtent([0.05, 4]).on('zoom', event => ui.viewport.attr('transform', event.transform));
  ui.svg.call(ui.zoom).on('dblclick.zoom', null).on('click', () => clearSelection());
  ui.packages = el('div', {id: 'packages', hidden: true});
  ui.launch = el('div', {id: 'launch', hidden: true});
  ui.hint = el('div', {id: 'hint', hidden: true});
  ui.stage = el('div', {id: 'stage'}, ui.svg.node(), ui.hint, legend(), ui.packages, ui.launch);
  ui.panel = el('aside', {id: 'panel'});
  document.body.append(header, el('main', {}, side, ui.stage, ui.panel));

  ui.config.addEventListener('change', () => setConfig(Number(ui.config.value)));
  ui.layout.addEventListener('change', () => { app.layout = ui.layout.value; renderGraph(); });
  ui.fit.addEventListener('click', () => fit());
  ui.search.addEventListener('input', () => search(false));
  ui.search.addEventListener('keydown', event => { if (event.key === 'Enter') search(true); });
  ui.tabGraph.addEventListener('click', () => showTab('graph'));
  ui.tabPackages.addEventListener('click', () => showTab('packages'));
  ui.tabLaunch.addEventListener('click', () => showTab('launch'));
  document.addEventListener('keydown', event => { if (event.key === 'Escape') clearSelection(); });
}

// The legend folds to its title (it starts folded on a big configuration).
function legend() {
  const fold = el('button', {id: 'legend-fold', type: 'button', title: 'show or hide the legend'}, 'legend');
  const box = el('div', {id: 'legend'}, fold);
  fold.addEventListener('click', () => foldLegend(!box.classList.contains('folded')));
  const svg = d3.select(box).append('svg').attr('width', 150).attr('height', 202);
  const samples = [['node', 'node instance'], ['topic', 'topic'], ['service', 'service'], ['action', 'action'], ['parameter', 'parameter']];
  samples.forEach(([kind, label], i) => {
    const v = {kind, w: 40, h: kind === 'parameter' ? 14 : 18};
    const g = svg.append('g').attr('class', 'vertex k-' + kind).attr('transform', `translate(26,${14 + i * 24})`);
    g.append('path').attr('class', 'shape').attr('d', shapePath(v));
    svg.append('text').attr('x', 54).attr('y', 18 + i * 24).text(label);
  });
  const y = 14 + samples.length * 24;
  svg.append('path').attr('class', 'edge conditional').attr('d', `M6,${y} L46,${y}`);
  svg.append('text').attr('x', 54).attr('y', y + 4).text('conditional');
  const u = svg.append('g').attr('class', 'vertex k-topic unresolved').attr('transform', `translate(26,${y + 24})`);
  u.append('path').attr('class', 'shape').attr('d', shapePath({kind: 'topic', w: 40, h: 18}));
  u.append('g').attr('class', 'badge').attr('transform', 'translate(18,-9)')
    .call(g => { g.append('circle').attr('r', 6); g.append('text').attr('dy', '0.35em').text('?'); });
  svg.append('text').attr('x', 54).attr('y', y + 28).text('name has ?');
  const p = svg.append('g').attr('class', 'vertex k-node incomplete').attr('transform', `translate(26,${y + 48})`);
  p.append('path').attr('class', 'shape').attr('d', shapePath({kind: 'node', w: 40, h: 18}));
  svg.append('text').attr('x', 54).attr('y', y + 52).text('partial interface');
  return box;
}

function foldLegend(folded) {
  document.getElementById('legend').classList.toggle('folded', folded);
}

// ---- state changes -------------------------------------------------------------------------

function setConfig(i) {
  const config = CONFIGS[i] || {name: '(no configuration)'};
  app.config = config;
  app.index = indexConfiguration(config, app.nodeModels);
  app.options.collapsed.clear();
  app.selected = null;
  app.focus = null;
  app.touched = false;
  // A big configuration opens with its namespaces collapsed into boxes, as many levels
  // open as keep it readable.
  const size = buildView(app.index, app.options).vertices.length;
  app.big = size > BIG ? size : 0;
  if (app.big) openLevels();
  for (const [name, box] of app.index.tree.boxes) if (box.params) app.options.collapsed.add(name);
  foldLegend(!!app.big);
  renderLists();
  renderGraph();
  if (!ui.packages.hidden) renderPackages();
  if (!ui.launch.hidden) renderLaunch();
  showPanel(overview(config));
}

// a finding lists every configuration it was found in (one problem, one finding)
app.configFindings = () => app.findings.filter(f => !f.configuration || !app.config ||
  (f.configurations || [f.configuration]).includes(app.config.name));
app.findingsFor = id => app.configFindings().filter(f => (f.entities || []).includes(id));

// node models by name ("pkg/exec"), for the completeness of the instances that run them
app.nodeModels = new Map((MODEL.packages || []).flatMap(p => (p.nodes || []).map(n => [n.name || `${n.package}/${n.executable}`, n])));

// The workspace's diagnostics that concern this configuration: those in files it reads
// (its launch files, the sources of the nodes it runs) and those of no file.
function configDiagnostics(config) {
  const files = new Set();
  for (const link of config.links || []) if (link.location && link.location.file) files.add(link.location.file);
  for (const node of config.nodes || []) {
    if (node.location && node.location.file) files.add(node.location.file);
    const model = node.node ? app.nodeModels.get(node.node) : null;
    for (const source of (model && model.sources) || []) files.add(source);
    for (const call of (model && model.calls) || []) if (call.location && call.location.file) files.add(call.location.file);
  }
  for (const launch of config.launch || []) files.add(launch);
  const mine = (MODEL.diagnostics || []).filter(d => !d.location || !d.location.file || files.has(d.location.file));
  return [...(config.diagnostics || []), ...mine];
}

// Findings grouped by rule (most severe first), each group with its count, folded
// open when there are few.
function findingGroups(found) {
  const groups = new Map();
  for (const f of found) {
    if (!groups.has(f.rule)) groups.set(f.rule, []);
    groups.get(f.rule).push(f);
  }
  const rank = items => Math.min(...items.map(f => SEVERITIES.indexOf(f.severity)));
  return [...groups.entries()].sort((a, b) => rank(a[1]) - rank(b[1]) || compareText(a[0], b[0]))
    .map(([rule, items]) => {
      const group = el('details', {class: 'finding-group', 'data-rule': rule},
        el('summary', {}, severityBadge(items[0].severity), el('span', {class: 'item-title'}, items[0].title || rule),
          el('span', {class: 'count'}, String(items.length))),
        ...items.map(f => findingItem(f, app)));
      if (groups.size <= 3 || items.length <= 3) group.open = true;
      return group;
    });
}

// A capture of the running system beside the graph (`report --live`): per kind, what is
// in both, only live (not in the graph) and only in the model (dashed in the graph).
const LIVE = DATA.live || null;
const LIVE_KINDS = {nodes: 'node', topics: 'topic', services: 'service', actions: 'action'};

function liveScores() {
  return LIVE && app.config ? (LIVE[app.config.name] || null) : null;
}

function renderLive() {
  const found = liveScores();
  ui.live.hidden = !found;
  if (!found) return;
  const list = (label, items) => items.length ? [el('div', {class: 'live-part'}, label),
    el('ul', {}, items.map(item => el('li', {}, el('code', {}, item))))] : [];
  ui.live.replaceChildren(el('h3', {}, 'Live capture'),
    el('p', {class: 'muted'}, 'dashed in the graph: in the model, not seen live'),
    ...found.scores.map(s => {
      const differs = s.differs || [];
      const onlyLive = differs.length ? [] : s.missing, onlyModel = differs.length ? [] : s.extra;
      const parts = [`${s.matched} both`, `${onlyLive.length} only live`, `${onlyModel.length} only in the model`];
      if (s.differs) parts.push(`${differs.length} differ`);
      const item = el('details', {class: 'live-kind', 'data-kind': s.kind},
        el('summary', {}, el('span', {class: 'item-title'}, s.kind), ' ', el('span', {class: 'muted'}, parts.join(', '))),
        ...list('only live', onlyLive), ...list('only in the model', onlyModel),
        ...list('differs', differs), ...list('both', s.both || []));
      if (onlyLive.length || onlyModel.length || differs.length) item.open = true;
      return item;
    }));
}

// The ids of the graph's entities that the capture did not see.
function staticOnly() {
  const found = liveScores();
  const ids = new Set();
  for (const s of (found && found.scores) || []) {
    const kind = LIVE_KINDS[s.kind];
    if (kind) for (const name of s.extra) ids.add(`${kind}:${name}`);
  }
  return ids;
}

function renderLists() {
  renderLive();
  const found = bySeverity(app.configFindings());
  ui.findings.replaceChildren(el('h3', {}, `Findings (${found.length})`),
    ...(found.length ? findingGroups(found) : [el('p', {class: 'muted'}, 'No query findings.')]));
  const diags = bySeverity(configDiagnostics(app.config));
  ui.diagnostics.replaceChildren(el('h3', {}, `Extraction diagnostics (${diags.length})`),
    ...diags.slice(0, 500).map(d => diagnosticItem(d, app)),
    ...(diags.length > 500 ? [el('p', {class: 'muted'}, `${diags.length - 500} more not listed`)] : []));
  const groups = namespaceNames();
  const all = open => el('a', {href: '#', class: 'all', 'data-all': open ? 'open' : 'collapse', onclick: event => {
    event.preventDefault(); setCollapsed(open ? [] : groups);
  }}, open ? 'open all' : 'collapse all');
  ui.namespaces.replaceChildren(el('h3', {}, 'Namespaces'),
    ...(groups.length > 1 ? [el('div', {class: 'all-row'}, all(true), ' \u00b7 ', all(false))] : []),
    ...(groups.length ? groups.map(name => {
    const box = el('input', {type: 'checkbox', 'data-namespace': name});
    box.checked = app.options.collapsed.has(name);
    box.addEventListener('change', () => toggleCollapse(name));
    const depth = app.index.tree.boxes.get(name).depth;
    return el('label', {class: 'check', style: `padding-left: ${(depth - 1) * 14}px`}, box, ' collapse ', el('code', {}, name));
  }) : [el('p', {class: 'muted'}, 'everything is in /')]));
}

// Every namespace box, parents before their children.
function namespaceNames() {
  return [...app.index.tree.boxes.keys()].sort(compareText);
}

// Boxes deeper than d collapsed, for the largest d that draws at most BIG elements.
function openLevels() {
  const boxes = app.index.tree.boxes, set = app.options.collapsed;
  const deepest = Math.max(0, ...[...boxes.values()].map(b => b.depth));
  const shut = d => { set.clear(); for (const [name, b] of boxes) if (b.depth > d || b.params) set.add(name); };
  let d = 0;
  while (d < deepest) {
    shut(d + 1);
    if (buildView(app.index, app.options).vertices.length > BIG) break;
    d++;
  }
  shut(d);
}

// Opening a namespace lays out its content and zooms to it; the others stay as they are.
function toggleCollapse(name) {
  app.touched = true;
  const set = app.options.collapsed;
  const opening = set.has(name);
  if (opening) set.delete(name); else set.add(name);
  syncCollapsed();
  renderGraph(opening ? name : null);
}

function setCollapsed(names) {
  app.touched = true;
  app.options.collapsed.clear();
  for (const name of names) app.options.collapsed.add(name);
  syncCollapsed();
  renderGraph();
}

function syncCollapsed() {
  const set = app.options.collapsed;
  for (const box of ui.namespaces.querySelectorAll('input')) box.checked = set.has(box.getAttribute('data-namespace'));
}

function showHint() {
  const shut = app.view ? app.view.vertices.filter(v => v.kind === 'namespace').length : 0;
  ui.hint.hidden = !shut || !ui.packages.hidden || !ui.launch.hidden;
  if (!shut) return;
  const prefixed = [...app.index.tree.boxes.values()].some(b => b.prefix);
  const unresolved = [...app.index.tree.boxes.values()].some(b => b.unresolved);
  ui.hint.replaceChildren(
    el('strong', {}, 'Click a namespace to open it.'), ' ',
    app.big && !app.touched ? `This configuration has ${app.big.toLocaleString('en')} elements, so ${shut} namespaces start collapsed; ` +
      'each box counts what it holds, and a thick arrow stands for every link between two boxes (hover for the count). ' +
      (prefixed ? 'Names that share their first word (camera_driver, /camera/image) are boxed together as /camera*. ' : '') +
      (unresolved ? 'Names the tool could not resolve (a \u2018?\u2019 in their namespace) are boxed as \u2018? unresolved names\u2019. ' : '') +
      'Search + Enter opens the namespace of a name. '
      : `${shut} namespace${shut === 1 ? '' : 's'} collapsed. `,
    el('a', {href: '#', id: 'open-all', onclick: event => { event.preventDefault(); setCollapsed([]); }}, 'open all'));
}

function renderGraph(opened) {
  if (app.sim) { app.sim.stop(); app.sim = null; }
  app.view = buildView(app.index, app.options);
  const handlers = {
    click: v => v.kind === 'namespace' ? toggleCollapse(v.name) : app.select(v.id, false),
    collapse: toggleCollapse,
  };
  const stage = ui.svg.node().getBoundingClientRect();
  const opts = {aspect: stage.width && stage.height ? stage.width / stage.height : 1.6, tree: app.view.tree};
  app.view.rects = layeredLayout(app.view.vertices, app.view.edges, opts);
  if (app.layout === 'force') app.view.rects = new Map();
  app.drawn = drawGraph(ui.viewport, app.view, handlers);
  if (LIVE) {
    const notSeen = staticOnly();
    app.drawn.vertexSel.classed('static-only', v => notSeen.has(v.id));
  }
  if (app.layout === 'force') app.sim = forceLayout(app.view.vertices, app.view.edges, () => app.drawn.update(), opts);
  const inside = opened && app.layout !== 'force' ? app.view.vertices.filter(v => v.path.includes(opened)) : [];
  showHint();
  if (inside.length) fit(inside, READABLE); else fit();
  reapplyFocus();
}

// Fit these vertices (or all, with the namespace boxes) to the stage, never below scale
// `least`: centred across, from the top down (data flows from the top left), and when
// too big for the stage showing its start.
function fit(only, least = 0) {
  const vs = only || (app.view ? app.view.vertices : []);
  const box = ui.svg.node().getBoundingClientRect();
  if (!vs.length || !box.width) return;
  let x0 = Math.min(...vs.map(v => v.x - v.w / 2)), x1 = Math.max(...vs.map(v => v.x + v.w / 2));
  let y0 = Math.min(...vs.map(v => v.y - v.h / 2)), y1 = Math.max(...vs.map(v => v.y + v.h / 2));
  const names = only ? new Set(vs.flatMap(v => v.path)) : null;
  for (const [name, r] of groupRects(app.view)) {
    if (names && !names.has(name)) continue;
    x0 = Math.min(x0, r.x0); x1 = Math.max(x1, r.x1); y0 = Math.min(y0, r.y0); y1 = Math.max(y1, r.y1);
  }
  // and the bends of the edges between them: a long edge of the layered layout may run
  // above every vertex (under the hint, out of sight, were it left out)
  const ids = new Set(vs.map(v => v.id));
  for (const e of app.view ? app.view.edges : []) {
    if (!e.points || !ids.has(e.source.id) || !ids.has(e.target.id)) continue;
    for (const [x, y] of e.points) {
      x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
    }
  }
  x0 -= 30; x1 += 30; y0 -= 20; y1 += 30;
  const top = ui.hint.hidden ? 0 : ui.hint.offsetHeight + 8;  // keep clear of the hint
  const k = Math.max(least, Math.min(1.4, box.width / (x1 - x0), (box.height - top) / (y1 - y0)));
  const tx = k * (x1 - x0) > box.width ? -k * x0 : box.width / 2 - k * (x0 + x1) / 2;
  const ty = top - k * y0;
  ui.svg.call(ui.zoom.transform, d3.zoomIdentity.translate(tx, ty).scale(k));
}

function centreOn(id) {
  const v = app.view.vertices.find(x => x.id === id || (x.kind === 'namespace' && x.entity.members.some(m => m.id === id)));
  if (!v) return;
  const box = ui.svg.node().getBoundingClientRect();
  const k = Math.max(d3.zoomTransform(ui.svg.node()).k, 0.8);
  ui.svg.transition().duration(300).call(ui.zoom.transform,
    d3.zoomIdentity.translate(box.width / 2 - k * v.x, box.height / 2 - k * v.y).scale(k));
}

// focus: {ids: Set of entity ids lit, candidates: Set, selected: id}
function setFocus(focus) {
  app.focus = focus;
  reapplyFocus();
}

function reapplyFocus() {
  const focus = app.focus;
  if (!app.drawn) return;
  ui.svg.classed('focus', !!focus);
  const lit = v => !!focus && (focus.ids.has(v.id) || (v.kind === 'namespace' && v.entity.members.some(m => focus.ids.has(m.id))));
  app.drawn.vertexSel
    .classed('hl', lit)
    .classed('selected', v => !!focus && v.id === focus.selected)
    .classed('candidate', v => !!focus && focus.candidates.has(v.id));
  app.drawn.edgeSel.classed('hl', e => lit(e.source) && lit(e.target));
}

app.select = (id, centre) => {
  const entity = app.index.entities.get(id);
  if (!entity) return;
  if (centre && entity.path.some(name => app.options.collapsed.has(name))) {
    for (const name of entity.path) app.options.collapsed.delete(name);
    syncCollapsed();
    renderGraph();
  }
  app.selected = id;
  const ids = new Set([id]);
  for (const entry of entity.links) { ids.add(entry.node.id); ids.add(entry.resource.id); }
  const candidates = new Set(entity.item.candidates || []);
  for (const c of candidates) ids.add(c);
  setFocus({ids, candidates, selected: id});
  showPanel(entityPanel(entity, app));
  if (centre) { showTab('graph'); centreOn(id); }
};

app.showFinding = finding => {
  setFocus({ids: new Set(finding.entities || []), candidates: new Set(), selected: null});
  for (const item of document.querySelectorAll('.item.finding')) item.classList.toggle('active', item.__finding === finding);
  showPanel(findingPanel(finding, app));
  showTab('graph');
};

app.showPanel = showPanel;
function showPanel(parts) {
  ui.panel.replaceChildren(...parts.filter(Boolean));
  ui.panel.scrollTop = 0;
}

function clearSelection() {
  app.selected = null;
  setFocus(null);
  showPanel(overview(app.config));
}

function overview(config) {
  const count = key => (config[key] || []).length;
  return [
    el('div', {class: 'panel-kind'}, 'configuration'),
    el('h2', {class: 'panel-title'}, config.name),
    field('launch', (config.launch || []).join(', ') || '?'),
    Object.keys(config.args || {}).length ? field('arguments', Object.entries(config.args).map(([k, v]) => `${k}:=${v}`).join('  ')) : null,
    field('contains', `${count('nodes')} nodes, ${count('topics')} topics, ${count('services')} services, ` +
      `${count('actions')} actions, ${count('parameters')} parameters`),
    el('p', {class: 'muted help'}, 'Click an element to see its details, links and source; click a finding to ' +
      'highlight what it involves. Drag to move, scroll to zoom, Esc to clear.'),
  ];
}

function search(go) {
  const text = ui.search.value.trim().toLowerCase();
  if (!text) { setFocus(null); return; }
  const ids = new Set([...app.index.entities.values()].filter(e => e.name.toLowerCase().includes(text)).map(e => e.id));
  setFocus({ids, candidates: new Set(), selected: null});
  if (go && ids.size) app.select([...ids][0], true);
}

function showTab(name) {
  const packages = name === 'packages', launch = name === 'launch';
  ui.tabGraph.classList.toggle('active', !packages && !launch);
  ui.tabPackages.classList.toggle('active', packages);
  ui.tabLaunch.classList.toggle('active', launch);
  ui.packages.hidden = !packages;
  ui.launch.hidden = !launch;
  ui.svg.style('display', packages || launch ? 'none' : null);
  document.getElementById('legend').hidden = packages || launch;
  showHint();
  if (packages) renderPackages();
  if (launch) renderLaunch();
}

// The Launch view, with the node selected in the graph marked and scrolled to.
function renderLaunch() {
  ui.launch.replaceChildren(el('h2', {class: 'view-title'}, 'Launch: the files, groups and nodes of this configuration'),
    ...launchView(app.config, app));
  const row = markLaunchSelection(ui.launch, app.selected);
  if (row) row.scrollIntoView({block: 'center'});
}

// A node row selects its node in the graph; any other box (or a node not in the graph)
// shows its launch lines.
app.chooseLaunchItem = (item, box, node) => {
  if (node && app.index.entities.has(node.id)) {
    app.select(node.id, true);
    return;
  }
  markLaunchSelection(ui.launch, null);
  box.classList.add('chosen');
  showPanel(launchItemPanel(item, app));
};

function renderPackages() {
  ui.packages.replaceChildren(el('h2', {class: 'view-title'}, 'Packages: the nodes each provides and their interfaces'),
    ...packageView(MODEL, app));
}

skeleton();
// the report opens on the first configuration that starts a node (a launch file that
// includes nothing the workspace has, or only another robot's parts, starts none)
const opening = Math.max(0, CONFIGS.findIndex(c => (c.nodes || []).length > 0));
ui.config.value = String(opening);
setConfig(opening);
window.harosReport = {ready: true, scriptMs: performance.now() - started, readyAt: performance.now()};
