// Runs a G-code file through the independent interpreters gcode-parser and gcode-toolpath (cncjs)
// and prints every move as JSON, so the C++ tests check lastcut's G-code against someone else's
// reading of it. Usage: node gcode_dump.js FILE.nc NODE_MODULES_DIR [ROTARY_AXIS_LETTER]
// Output: {"moves": [{"motion", "x1","y1","z1","x2","y2","z2", "cx","cy" (arcs), "a1","a2",
//          "spindle","coolant"}...]} on stdout; exit 2 with a message when anything is missing.
'use strict';
const fs = require('fs');
const path = require('path');

const [file, modulesDir, axisArgument] = process.argv.slice(2);
if (!file || !modulesDir) {
  console.error('usage: node gcode_dump.js FILE.nc NODE_MODULES_DIR [A|C]');
  process.exit(2);
}
const Toolpath = require(path.join(modulesDir, 'gcode-toolpath'));
const axis = (axisArgument || 'A').toUpperCase();

const moves = [];
let pending = [];
let angle = 0;
const toolpath = new Toolpath({
  position: { x: 0, y: 0, z: 0 },
  addLine: (modal, v1, v2) => {
    pending.push({ motion: modal.motion, x1: v1.x, y1: v1.y, z1: v1.z, x2: v2.x, y2: v2.y, z2: v2.z,
                   spindle: modal.spindle, coolant: modal.coolant });
  },
  addArcCurve: (modal, v1, v2, v0) => {
    pending.push({ motion: modal.motion, x1: v1.x, y1: v1.y, z1: v1.z, x2: v2.x, y2: v2.y, z2: v2.z,
                   cx: v0.x, cy: v0.y, spindle: modal.spindle, coolant: modal.coolant });
  },
});

const text = fs.readFileSync(file, 'utf8');
toolpath.loadFromStringSync(text, (line) => {
  const before = angle;
  for (const [letter, value] of line.words) {
    if (letter === axis) angle = value;
  }
  for (const move of pending) {
    move.a1 = before;
    move.a2 = angle;
    moves.push(move);
  }
  pending = [];
});
process.stdout.write(JSON.stringify({ moves: moves }));
