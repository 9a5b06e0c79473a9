// The operator page: reads /api/overview once, then follows /api/events (Server-Sent Events) and
// redraws from what they say; the overview is read again only when the stream says it missed
// something (resync), every 15 s for the counts, or after an action. All text is set with
// textContent: nothing from a scan name or a reason can become markup.
'use strict';

const COLUMNS = [
  ['incoming', 'Incoming'], ['computing', 'Computing'], ['waiting', 'Waiting for batch or hide'],
  ['nested', 'Nested'], ['sending', 'Sending'], ['done', 'Done'], ['failed', 'Failed'], ['held', 'Held'],
];
// The store's word for a job's state -> the column it is shown in (spool and ledger words).
const COLUMN_OF = {
  claimed: 'computing', ready: 'computing', computing: 'computing', computed: 'waiting', batched: 'nested',
  sending: 'sending', cut: 'done', done: 'done', skipped: 'done', failed: 'failed', held: 'held',
};

const state = { overview: null, jobs: new Map(), cutters: {}, incoming: [], source: null, shownJob: null, cutMaps: {}, tables: {},
                redraw: { queue: false, cutters: false, timer: null } };
// Live events redraw at most this often: a busy shop sends tens of events a second (every cutter's
// progress), and redrawing the queue and the table's picture for each one kept a screen's
// processor busy; a quarter of a second is well inside the promised 1 s.
const REDRAW_EVERY_MS = 250;
const SVG = 'http://www.w3.org/2000/svg';

const $ = (id) => document.getElementById(id);
function el(tag, text, className) {
  const node = document.createElement(tag);
  if (text !== undefined) node.textContent = text;
  if (className) node.className = className;
  return node;
}
function token() { return $('token').value.trim(); }
function say(text, ok) {
  const message = $('message');
  message.textContent = text;
  message.className = ok ? 'ok' : 'error';
}

async function act(method, url, body) {
  const headers = {};
  if (token()) headers.Authorization = 'Bearer ' + token();
  const answer = await fetch(url, { method, headers, body });
  const text = (await answer.text()).trim();
  say(text, answer.ok);
  await loadOverview();
  return answer.ok;
}

async function loadOverview() {
  const answer = await fetch('/api/overview', { cache: 'no-store' });
  if (!answer.ok) { say(await answer.text(), false); return; }
  const overview = await answer.json();
  state.overview = overview;
  state.jobs = new Map(overview.jobs.map((job) => [job.id, job]));
  state.incoming = overview.incoming;
  Object.assign(state.cutters, overview.live_cutters);
  draw();
}

function jobEvent(event) {
  const known = state.jobs.get(event.id) || {};
  state.jobs.set(event.id, {
    ...known, id: event.id, state: event.stage, scan: event.scan || known.scan, order: event.order || known.order,
    reason: event.reason, note: event.note, cutter: event.cutter, batch: event.batch,
  });
  state.incoming = state.incoming.filter((name) => name !== event.scan);
  redrawSoon('queue');
  if (state.shownJob === event.id) showJob(event.id);
  // A batch formed, taken or ended: its list comes with the overview (read once for a burst).
  if (['batched', 'sending', 'cut', 'held'].includes(event.stage) && !state.batchReload) {
    state.batchReload = setTimeout(() => { state.batchReload = null; loadOverview(); }, 700);
  }
}

// Marks a part of the page to redraw and draws every marked part once, REDRAW_EVERY_MS from the first mark.
function redrawSoon(part) {
  state.redraw[part] = true;
  if (state.redraw.timer) return;
  state.redraw.timer = setTimeout(() => {
    const { queue, cutters } = state.redraw;
    state.redraw = { queue: false, cutters: false, timer: null };
    if (queue) drawQueue();
    if (cutters) drawCutters();
  }, REDRAW_EVERY_MS);
}

// The cut map of a batch (its pieces on the table and their bytes in the cut file), read once.
function cutMap(batch) {
  if (!(batch in state.cutMaps)) {
    state.cutMaps[batch] = null;
    fetch(`/api/batches/${encodeURIComponent(batch)}/files/cut-map.json`, { cache: 'no-store' })
      .then((answer) => (answer.ok ? answer.json() : null))
      .then((map) => { state.cutMaps[batch] = map; if (map) drawCutters(); })
      .catch(() => {});
  }
  return state.cutMaps[batch];
}

// The layout on the cutter's table, drawn once per batch: {svg, shapes: [{piece, outline, title, status}]}.
function tablePicture(map) {
  const svg = document.createElementNS(SVG, 'svg');
  svg.setAttribute('class', 'table');
  const shapes = [];
  const points = map.pieces.flatMap((piece) => piece.outline_mm);
  if (points.length === 0) return { svg, shapes };
  const xs = points.map((p) => p[0]);
  const ys = points.map((p) => p[1]);
  const [x0, x1, y0, y1] = [Math.min(...xs) - 10, Math.max(...xs) + 10, Math.min(...ys) - 10, Math.max(...ys) + 10];
  svg.setAttribute('viewBox', `${x0} ${-y1} ${x1 - x0} ${y1 - y0}`);  // y up, as on the table
  for (const piece of map.pieces) {
    const outline = document.createElementNS(SVG, 'polygon');
    outline.setAttribute('points', piece.outline_mm.map((p) => `${p[0]},${-p[1]}`).join(' '));
    outline.dataset.label = piece.label;
    const title = document.createElementNS(SVG, 'title');
    outline.append(title);
    const px = piece.outline_mm.map((p) => p[0]);
    const py = piece.outline_mm.map((p) => p[1]);
    const label = document.createElementNS(SVG, 'text');
    label.setAttribute('x', (Math.min(...px) + Math.max(...px)) / 2);
    label.setAttribute('y', -(Math.min(...py) + Math.max(...py)) / 2);
    label.setAttribute('font-size', Math.max(8, (y1 - y0) / 30));
    label.setAttribute('text-anchor', 'middle');
    label.textContent = piece.label;
    svg.append(outline, label);
    shapes.push({ piece, outline, title, status: null });
  }
  return { svg, shapes };
}

// Each piece cut, being cut or waiting, by the bytes sent; only the pieces whose state changed are
// touched (a cutter reports progress many times a second, and redrawing a picture of a hundred
// pieces for each report kept a screen's processor busy).
function markPieces(table, bytesSent) {
  for (const shape of table.shapes) {
    const { piece } = shape;
    const status = bytesSent >= piece.end_byte ? 'cut' : bytesSent >= piece.first_byte ? 'cutting' : 'waiting';
    if (status === shape.status) continue;
    shape.status = status;
    shape.outline.setAttribute('class', 'piece ' + status);
    shape.title.textContent = `${piece.label} (${status})`;
  }
}

// Cutter `name`'s table picture for `batch`, kept while the batch is on its table.
function tableOf(name, batch, map) {
  const kept = state.tables[name];
  if (kept && kept.batch === batch) return kept;
  state.tables[name] = { batch, ...tablePicture(map) };
  return state.tables[name];
}

function drawCutters() {
  const box = $('cutters');
  box.replaceChildren();
  const names = Object.keys(state.cutters).sort();
  if (names.length === 0) box.append(el('p', 'no cutter has reported yet'));
  for (const name of names) {
    const cutter = state.cutters[name];
    const card = el('div', undefined, 'card cutter');
    card.dataset.cutter = name;
    card.append(el('h3', name), el('div', cutter.state, 'state state-' + cutter.state));
    if (cutter.batch) card.append(el('div', 'batch ' + cutter.batch));
    if (cutter.bytes_total) {
      const bar = el('progress');
      bar.max = cutter.bytes_total;
      bar.value = cutter.bytes_sent;
      const lines = cutter.lines_total ? `, ${cutter.lines_sent} of ${cutter.lines_total} lines acknowledged` : '';
      card.append(bar, el('div', `${Math.round(100 * cutter.bytes_sent / cutter.bytes_total)} % sent${lines}`, 'progress-text'));
    }
    if (cutter.reason) card.append(el('div', cutter.reason, 'reason'));
    // Pause: the cutter finishes the batch on its table and starts no other until resumed.
    const paused = cutter.state === 'paused' || (state.overview && name in (state.overview.paused_cutters || {}));
    const toggle = el('button', paused ? 'Resume' : 'Pause', paused ? 'resume' : 'pause');
    toggle.addEventListener('click', () => act('POST', `/api/cutters/${encodeURIComponent(name)}/${paused ? 'resume' : 'pause'}`));
    card.append(toggle);
    const map = cutter.batch ? cutMap(cutter.batch) : null;
    if (map) {
      const table = tableOf(name, cutter.batch, map);
      markPieces(table, cutter.bytes_sent);
      card.append(table.svg);
      const current = table.shapes.find((shape) => shape.status === 'cutting');
      const cut = table.shapes.filter((shape) => shape.status === 'cut').length;
      card.append(el('div', `${cut} of ${map.pieces.length} pieces cut` + (current ? `; cutting ${current.piece.label}` : ''), 'pieces-text'));
    }
    box.append(card);
  }
  // Only the batches on the tables now: a page left open for weeks keeps no map of every batch cut.
  const onTables = new Set(names.map((name) => state.cutters[name].batch).filter(Boolean));
  for (const batch of Object.keys(state.cutMaps)) if (!onTables.has(batch)) delete state.cutMaps[batch];
  const select = $('hide-cutter');
  const chosen = select.value;
  select.replaceChildren(...names.map((name) => el('option', name)));
  if (names.includes(chosen)) select.value = chosen;
}

function drawQueue() {
  const lists = Object.fromEntries(COLUMNS.map(([key]) => [key, []]));
  for (const name of state.incoming) lists.incoming.push({ label: name });
  for (const job of state.jobs.values()) {
    const column = COLUMN_OF[job.state] || 'computing';
    lists[column].push({ job, label: `${job.id} ${job.order ? '[' + job.order + '] ' : ''}${job.scan || ''}` });
  }
  const box = $('queue');
  box.replaceChildren();
  for (const [key, title] of COLUMNS) {
    const column = el('div', undefined, 'column ' + key);
    column.id = 'column-' + key;
    const heading = el('h3', title);
    heading.append(el('span', String(lists[key].length), 'count'));
    const list = el('ul');
    for (const item of lists[key].slice(-40)) {
      const line = el('li');
      if (item.job) {
        line.dataset.job = item.job.id;
        const link = el('a', item.label);
        link.href = '#job/' + encodeURIComponent(item.job.id);
        line.append(link);
        if (item.job.reason && (key === 'held' || key === 'failed')) line.append(el('div', item.job.reason, 'reason'));
        // A job of several materials: which pieces wait for which material.
        if (item.job.parts) line.append(el('div', 'parts: ' + item.job.parts, 'parts'));
        if (key === 'held' || key === 'failed') {
          const again = el('button', 'Requeue', 'requeue');
          again.addEventListener('click', () => act('POST', `/api/jobs/${encodeURIComponent(item.job.id)}/requeue`));
          line.append(again);
        }
      } else {
        line.textContent = item.label;
      }
      list.append(line);
    }
    column.append(heading, list);
    box.append(column);
  }
}

// The hides nested lately: each one's layout, how much of it the pieces use, and what is left.
function drawHides() {
  const hides = state.overview.hides || [];
  $('hide-cards').replaceChildren(...hides.map((hide) => {
    const card = el('div', undefined, 'card hide');
    card.dataset.hide = hide.hide;
    card.append(el('h3', 'hide ' + hide.hide), el('div', `${hide.state} - ${hide.material} on ${hide.cutter}`, 'state'));
    if (hide.batch) {
      const base = `/api/batches/${encodeURIComponent(hide.batch)}/files/`;
      const picture = el('img');
      picture.src = base + 'preview.svg';
      picture.alt = 'layout on hide ' + hide.hide;
      const figures = [`${hide.pieces} pieces`, `${Math.round(100 * hide.utilisation)} % of its usable area`];
      if (hide.offcut_area_m2 !== undefined) {
        figures.push(`offcut ${hide.offcut_area_m2.toFixed(2)} of ${hide.usable_area_m2.toFixed(2)} m\u00b2`);
      }
      if (hide.pairs_mirrored) {
        figures.push(`${hide.pairs_mirrored.mirrored} of ${hide.pairs_mirrored.pairs} pairs mirrored about the backbone`);
      }
      card.append(picture, el('div', figures.join(', '), 'figures'));
      if (hide.offcut_file) {
        const link = el('a', 'offcut (DXF)');
        link.href = base + encodeURIComponent(hide.offcut_file);
        card.append(link);
      }
    }
    return card;
  }));
}

// Bars of `values` (one per label), the largest one's height full; the value over each bar.
function barChart(title, labels, values, format) {
  const figure = el('figure', undefined, 'plot');
  const svg = document.createElementNS(SVG, 'svg');
  const [width, height, top, bottom] = [480, 160, 16, 18];
  svg.setAttribute('viewBox', `0 0 ${width} ${height}`);
  const most = Math.max(1e-9, ...values);
  const step = width / values.length;
  values.forEach((value, i) => {
    const barHeight = (height - top - bottom) * value / most;
    const bar = document.createElementNS(SVG, 'rect');
    bar.setAttribute('x', i * step + 2);
    bar.setAttribute('y', height - bottom - barHeight);
    bar.setAttribute('width', Math.max(1, step - 4));
    bar.setAttribute('height', barHeight);
    bar.setAttribute('class', 'bar');
    const tip = document.createElementNS(SVG, 'title');
    tip.textContent = `${labels[i]}: ${format(value)}`;
    bar.append(tip);
    svg.append(bar);
    const texts = [[labels[i], height - 4]];
    if (value > 0) texts.push([format(value), height - bottom - barHeight - 3]);
    for (const [text, y] of texts) {
      const label = document.createElementNS(SVG, 'text');
      label.setAttribute('x', i * step + step / 2);
      label.setAttribute('y', y);
      label.setAttribute('text-anchor', 'middle');
      label.textContent = text;
      svg.append(label);
    }
  });
  figure.append(svg, el('figcaption', title));
  return figure;
}

// The last 24 hours from the batches cut: pieces and jobs per hour (local time) and the yield per
// material (pieces' area over the material they used, weighted by pieces).
function drawDay() {
  const batches = state.overview.cut_last_24h || [];
  const hourMs = 3600 * 1000;
  const firstHour = Math.floor(Date.now() / hourMs) * hourMs - 23 * hourMs;
  const pieces = new Array(24).fill(0);
  const jobs = new Array(24).fill(0);
  const hours = pieces.map((_, i) => String(new Date(firstHour + i * hourMs).getHours()));
  const materials = {};
  for (const batch of batches) {
    const slot = Math.floor((Date.parse(batch.cut_at) - firstHour) / hourMs);
    if (slot >= 0 && slot < 24) { pieces[slot] += batch.pieces; jobs[slot] += batch.jobs; }
    const material = materials[batch.material] || (materials[batch.material] = { weighted: 0, pieces: 0 });
    material.weighted += batch.utilisation * batch.pieces;
    material.pieces += batch.pieces;
  }
  const names = Object.keys(materials).sort();
  const yields = names.map((name) => (materials[name].pieces ? materials[name].weighted / materials[name].pieces : 0));
  const totalPieces = pieces.reduce((a, b) => a + b, 0);
  const totalJobs = jobs.reduce((a, b) => a + b, 0);
  $('day-summary').textContent = `${totalJobs} job(s), ${totalPieces} pieces in ${batches.length} batch(es) cut` +
    (names.length ? '; yield ' + names.map((name, i) => `${name} ${Math.round(100 * yields[i])} %`).join(', ') : '');
  const count = (value) => String(value);
  const plots = [barChart('pieces cut per hour', hours, pieces, count), barChart('jobs cut per hour', hours, jobs, count)];
  if (names.length) plots.push(barChart('yield per material', names, yields, (value) => `${Math.round(100 * value)} %`));
  $('day-plots').replaceChildren(...plots);
}

function draw() {
  const overview = state.overview;
  if (!overview) return;
  $('headline').textContent = overview.headline;
  $('stations').replaceChildren(...overview.stations.concat(overview.cutters).map((line) => el('li', line)));
  const hideLines = overview.batches.slice();
  const waitingPieces = overview.pieces_waiting_for_hide || {};
  for (const [material, count] of Object.entries(overview.waiting_for_hide))
    hideLines.push(`${count} job(s) of ${material} wait for a hide` + (material in waitingPieces ? `, ${waitingPieces[material]} pieces` : ''));
  $('hide-lines').replaceChildren(...hideLines.map((line) => el('li', line)));
  // Nested and waiting: the last moment a batch can be taken back (its jobs are held, to requeue).
  const queued = overview.queued_batches || [];
  $('queued-batches').replaceChildren(...(queued.length ? queued.map((batch) => {
    const item = el('li', `batch ${batch.id} for ${batch.cutter}: ${batch.jobs} job(s), ${batch.pieces} pieces `);
    item.dataset.batch = batch.id;
    const cancel = el('button', 'Cancel', 'cancel');
    cancel.addEventListener('click', () => act('POST', `/api/batches/${encodeURIComponent(batch.id)}/cancel`));
    item.append(cancel);
    return item;
  }) : [el('li', 'none')]));
  drawCutters();
  drawQueue();
  drawHides();
  drawDay();
}

async function showJob(id) {
  state.shownJob = id;
  $('overview-view').hidden = true;
  $('job-view').hidden = false;
  $('job-title').textContent = 'Job ' + id;
  const answer = await fetch('/api/jobs/' + encodeURIComponent(id), { cache: 'no-store' });
  if (!answer.ok) { $('job-line').textContent = (await answer.text()).trim(); return; }
  const job = await answer.json();
  const line = job.line || {};
  const stage = (job.state && job.state.stage) || line.state || '';
  $('job-line').textContent = `${stage} ${line.order ? 'order ' + line.order : ''} ${line.scan || ''}`;
  const reason = (job.state && job.state.reason) || line.reason || '';
  // A done job's "reason" is its last note (where it was cut); only a held or failed one is a problem.
  $('job-reason').textContent = stage === 'held' || stage === 'failed' ? reason : '';
  $('job-line').textContent += stage === 'held' || stage === 'failed' ? '' : ` - ${reason}`;
  if (line.parts) $('job-line').textContent += ` (parts: ${line.parts})`;
  const requeue = $('job-requeue');
  requeue.hidden = !(stage === 'held' || stage === 'failed');
  requeue.onclick = () => act('POST', `/api/jobs/${encodeURIComponent(id)}/requeue`).then(() => showJob(id));
  const files = job.files || [];
  const base = `/api/jobs/${encodeURIComponent(id)}/files/`;
  $('job-pictures').replaceChildren(...files.filter((name) => name.endsWith('.svg')).map((name) => {
    const figure = el('figure');
    const picture = el('img');
    picture.src = base + name;
    picture.alt = name;
    figure.append(picture, el('figcaption', name));
    return figure;
  }));
  $('job-files').replaceChildren(...files.map((name) => {
    const item = el('li');
    const link = el('a', name);
    link.href = base + name;
    item.append(link);
    return item;
  }));
  const rows = [];
  const report = job.report || {};
  for (const [key, value] of Object.entries(report)) {
    if (typeof value !== 'object') rows.push([key, String(value)]);
  }
  $('job-report').replaceChildren(...rows.map(([key, value]) => {
    const row = el('tr');
    row.append(el('td', key), el('td', value));
    return row;
  }));
  const history = (job.state && job.state.history) || [];
  $('job-history').replaceChildren(...history.map((step) => el('li', `${step.at || ''} ${step.stage || ''} ${step.note || ''}`)));
}

function route() {
  const match = location.hash.match(/^#job\/(.+)$/);
  if (match) return showJob(decodeURIComponent(match[1]));
  state.shownJob = null;
  $('job-view').hidden = true;
  $('overview-view').hidden = false;
  return loadOverview();
}

function follow() {
  const source = new EventSource('/api/events');
  state.source = source;
  source.onopen = () => { $('live').textContent = 'live'; $('live').className = 'badge on'; loadOverview(); };
  source.onerror = () => { $('live').textContent = 'reconnecting'; $('live').className = 'badge off'; };
  source.addEventListener('job', (message) => jobEvent(JSON.parse(message.data)));
  source.addEventListener('cutter', (message) => {
    const cutter = JSON.parse(message.data);
    state.cutters[cutter.cutter] = cutter;
    redrawSoon('cutters');
  });
  source.addEventListener('resync', () => loadOverview());
}

$('token').value = sessionStorage.getItem('lastcut-token') || '';
$('token').addEventListener('change', () => sessionStorage.setItem('lastcut-token', token()));
$('token-form').addEventListener('submit', (event) => event.preventDefault());
$('hide-form').addEventListener('submit', async (event) => {
  event.preventDefault();
  const file = $('hide-file').files[0];
  if (!file) { say('choose a hide file first', false); return; }
  const cutter = $('hide-cutter').value;
  await act('POST', `/api/cutters/${encodeURIComponent(cutter)}/hides/${encodeURIComponent(file.name)}`, file);
});
window.addEventListener('hashchange', route);
route();
follow();
// A station's own events come live; on a ledger shop the other stations' jobs come through the
// overview, so it is read more often there.
let lastRead = 0;
setInterval(() => {
  const every = state.overview && state.overview.mode === 'ledger' ? 2000 : 15000;
  if (!state.shownJob && Date.now() - lastRead >= every) { lastRead = Date.now(); loadOverview(); }
}, 1000);
