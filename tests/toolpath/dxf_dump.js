// Reads a DXF file with the independent dxf-parser package (npm) and prints what it understood as
// JSON, so the C++ tests check lastcut's DXF against someone else's reading of it.
// Usage: node dxf_dump.js FILE.dxf NODE_MODULES_DIR
// Output: {"acadver", "insunits", "layers": [names], "entities": [{"type", "layer", "closed",
//          "points": [[x, y]...], "text"}]} on stdout; exit 2 with a message when anything is missing.
'use strict';
const fs = require('fs');
const path = require('path');

const [file, modulesDir] = process.argv.slice(2);
if (!file || !modulesDir) {
  console.error('usage: node dxf_dump.js FILE.dxf NODE_MODULES_DIR');
  process.exit(2);
}
const DxfParser = require(path.join(modulesDir, 'dxf-parser'));
const dxf = new DxfParser().parseSync(fs.readFileSync(file, 'utf8'));
if (!dxf) {
  console.error('dxf-parser returned nothing for ' + file);
  process.exit(2);
}
const header = dxf.header || {};
const layers = Object.keys((dxf.tables && dxf.tables.layer && dxf.tables.layer.layers) || {});
const entities = (dxf.entities || []).map((e) => ({
  type: e.type,
  layer: e.layer,
  closed: Boolean(e.shape),
  points: (e.vertices || (e.position ? [e.position] : e.startPoint ? [e.startPoint] : [])).map((v) => [v.x, v.y]),
  text: e.text || '',
}));
process.stdout.write(JSON.stringify({ acadver: header.$ACADVER || '', insunits: header.$INSUNITS || 0, layers, entities }));
