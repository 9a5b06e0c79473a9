// An independent PLC for lastcut's default Modbus register map (config/modbus-register-map.toml),
// built on the npm package modbus-serial's ServerTCP. It shares no code with lastcut, so lastcut's
// client is tested against someone else's Modbus framing and our written handshake, not against itself.
// Usage: node modbus_plc_server.js PORT OUT_FILE    (prints "ready: ..." once listening; 127.0.0.1 only)
"use strict";
const path = require("path");
const ModbusRTU = require(path.join(__dirname, "../../node/node_modules/modbus-serial"));
const fs = require("fs");

const [port, outFile] = process.argv.slice(2);
const R = { status: 0, error: 1, progress: 2, ack: 3, command: 10, jobId: 11, jobIdWords: 8, bytes: 19,
            number: 21, length: 22, window: 100, windowWords: 120 };
const S = { ready: 1, receiving: 2, loaded: 3, running: 4, done: 5, error: 6 };
const C = { begin: 1, start: 2, abort: 3, clearError: 4 };
const regs = new Array(256).fill(0);
regs[R.status] = S.ready;
let program = [];
let expected = 0;
let lastNumber = 0;

function fail(code) { regs[R.status] = S.error; regs[R.error] = code; }

function afterWrite(first, count) {
  const touches = (a) => a >= first && a < first + count;
  if (touches(R.command) && regs[R.command] !== 0) {
    const command = regs[R.command];
    regs[R.command] = 0;
    if (command === C.begin && regs[R.status] === S.ready) {
      program = [];
      expected = regs[R.bytes] * 65536 + regs[R.bytes + 1];
      lastNumber = 0;
      regs[R.ack] = 0;
      regs[R.status] = S.receiving;
    } else if (command === C.start && regs[R.status] === S.loaded) {
      regs[R.status] = S.running;
      regs[R.progress] = 0;
      setTimeout(() => { regs[R.progress] = 500; }, 100);
      setTimeout(() => {
        regs[R.progress] = 1000;
        regs[R.status] = S.done;
        let id = "";
        for (let i = 0; i < R.jobIdWords; i++) {
          for (const c of [regs[R.jobId + i] >> 8, regs[R.jobId + i] & 0xff]) if (c) id += String.fromCharCode(c);
        }
        fs.writeFileSync(outFile, Buffer.from(program));
        fs.writeFileSync(outFile + ".id", id);
      }, 250);
    } else if (command === C.abort) {
      regs[R.status] = S.ready;
    } else if (command === C.clearError) {
      regs[R.status] = S.ready; regs[R.error] = 0;
    }
  }
  if (touches(R.length) && regs[R.status] === S.receiving && regs[R.number] !== lastNumber) {
    lastNumber = regs[R.number];
    const length = regs[R.length];
    if (lastNumber !== regs[R.ack] + 1) return fail(201);
    if (length < 1 || length > 2 * R.windowWords) return fail(202);
    for (let i = 0; i < length; i++) {
      const word = regs[R.window + (i >> 1)];
      program.push(i % 2 === 0 ? word >> 8 : word & 0xff);
    }
    regs[R.ack] = lastNumber;
    if (program.length === expected) regs[R.status] = S.loaded;
  }
}

const vector = {
  getHoldingRegister: (addr) => {
    if (addr >= regs.length) throw { modbusErrorCode: 0x02, msg: "Illegal data address" };
    return regs[addr];
  },
  setRegister: (addr, value) => {
    if (addr >= regs.length) throw { modbusErrorCode: 0x02, msg: "Illegal data address" };
    regs[addr] = value;
    afterWrite(addr, 1);
  },
  setRegisterArray: (addr, values) => {
    if (addr + values.length > regs.length) throw { modbusErrorCode: 0x02, msg: "Illegal data address" };
    values.forEach((v, i) => { regs[addr + i] = v; });
    afterWrite(addr, values.length);
  },
};

const server = new ModbusRTU.ServerTCP(vector, { host: "127.0.0.1", port: Number(port), unitID: 1 });
server.on("initialized", () => console.log(`ready: 127.0.0.1:${port} (node modbus-serial ServerTCP)`));
server.on("serverError", (e) => { console.error(`server error: ${e.message}`); process.exit(1); });
process.on("SIGTERM", () => server.close(() => process.exit(0)));
