// N operator pages' requests without the browsers: what each page asks of lastcutd (app.js), made
// by plain HTTP clients in one Node process, so that the load bench measures what serving N pages
// costs the daemon, not what N browsers rendering on the same two cores cost the machine (on a
// shop floor the pages run on other computers). Each watcher reads the overview, follows
// /api/events (reconnecting with Last-Event-ID as a browser does), reads the overview again 0.7 s
// after an event that changes the batches and every 15 s, and reads the cut map of each batch a
// cutter starts. Every event's delay is its arrival time minus its published_ms (one machine, one
// clock). Writes one JSON line to OUT_FILE every second (pages, events, requests, the delay's
// median, p99 and max in ms, events later than 1 s), so the figures need no orderly exit.
// Usage: node stream_watchers.js URL PAGES OUT_FILE
'use strict';
const fs = require('fs');
const http = require('http');

const [url, pagesArgument, outFile] = process.argv.slice(2);
const base = new URL(url);
const late = [];
let requests = 0;
let failures = 0;

function get(path) {
  requests += 1;
  return new Promise((resolve) => {
    http.get({ host: base.hostname, port: base.port, path, headers: { Connection: 'close' } }, (res) => {
      res.resume();
      res.on('end', () => { if (res.statusCode !== 200) failures += 1; resolve(); });
    }).on('error', () => { failures += 1; resolve(); });
  });
}

function watcher() {
  let lastId = '';
  let reload = null;
  const maps = new Set();
  const overviewSoon = () => {
    if (!reload) reload = setTimeout(() => { reload = null; get('/api/overview'); }, 700);
  };
  const frame = (text) => {
    let kind = 'message';
    let data = '';
    for (const line of text.split('\n')) {
      if (line.startsWith('event: ')) kind = line.slice(7);
      else if (line.startsWith('data: ')) data += line.slice(6);
      else if (line.startsWith('id: ')) lastId = line.slice(4);
    }
    if (kind !== 'job' && kind !== 'cutter') {
      if (kind === 'resync') get('/api/overview');
      return;
    }
    const event = JSON.parse(data);
    if (event.published_ms) late.push(Date.now() - event.published_ms);
    if (kind === 'job' && ['batched', 'sending', 'cut', 'held'].includes(event.stage)) overviewSoon();
    if (kind === 'cutter' && event.batch && !maps.has(event.batch)) {
      maps.add(event.batch);
      get(`/api/batches/${encodeURIComponent(event.batch)}/files/cut-map.json`);
    }
  };
  const follow = () => {
    const headers = lastId ? { 'Last-Event-ID': lastId } : {};
    http.get({ host: base.hostname, port: base.port, path: '/api/events', headers }, (res) => {
      let buffer = '';
      res.setEncoding('utf8');
      res.on('data', (chunk) => {
        buffer += chunk;
        for (let end; (end = buffer.indexOf('\n\n')) >= 0;) {
          frame(buffer.slice(0, end));
          buffer = buffer.slice(end + 2);
        }
      });
      res.on('end', () => setTimeout(follow, 1000));
    }).on('error', () => setTimeout(follow, 1000));
  };
  get('/api/overview').then(follow);
  setInterval(() => get('/api/overview'), 15000);
}

function summary() {
  const sorted = late.slice().sort((a, b) => a - b);
  const at = (q) => (sorted.length ? sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))] : 0);
  return { pages: Number(pagesArgument), events: sorted.length, requests, failed_requests: failures, median_ms: at(0.5),
           p99_ms: at(0.99), max_ms: sorted.length ? sorted[sorted.length - 1] : 0,
           over_1s: sorted.filter((ms) => ms > 1000).length };
}

for (let i = 0; i < Number(pagesArgument); ++i) watcher();
console.error(`stream_watchers: ${pagesArgument} pages live`);
setInterval(() => {
  fs.writeFileSync(outFile + '.new', JSON.stringify(summary()) + '\n');
  fs.renameSync(outFile + '.new', outFile);
}, 1000);
