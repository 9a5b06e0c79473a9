// An independent Modbus client (npm modbus-serial) that runs one job through lastcut's default
// register map handshake (config/modbus-register-map.toml) against lastcut-sim's PLC.
// Usage: node modbus_client_job.js PORT PROGRAM_FILE JOB_ID   -> prints "done" and exits 0, or the error and exits 1.
"use strict";
const path = require("path");
const ModbusRTU = require(path.join(__dirname, "../../node/node_modules/modbus-serial"));
const fs = require("fs");

const [port, programFile, jobId] = process.argv.slice(2);
const R = { status: 0, error: 1, progress: 2, ack: 3, command: 10, jobId: 11, jobIdWords: 8, bytes: 19,
            number: 21, window: 100, windowWords: 120 };
const S = { ready: 1, receiving: 2, loaded: 3, running: 4, done: 5, error: 6 };
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

async function waitFor(client, predicate, what) {
  for (let i = 0; i < 100; i++) {
    const { data } = await client.readHoldingRegisters(R.status, 4);
    if (data[0] === S.error) throw new Error(`PLC error ${data[1]} while waiting for ${what}`);
    if (predicate(data)) return data;
    await sleep(20);
  }
  throw new Error(`timed out waiting for ${what}`);
}

async function main() {
  const program = fs.readFileSync(programFile);
  const client = new ModbusRTU();
  await client.connectTCP("127.0.0.1", { port: Number(port) });
  client.setID(1);
  client.setTimeout(1000);
  await waitFor(client, (d) => d[0] === S.ready, "ready");
  const id = new Array(R.jobIdWords).fill(0);
  for (let i = 0; i < jobId.length && i < 2 * R.jobIdWords; i++) id[i >> 1] |= jobId.charCodeAt(i) << (i % 2 === 0 ? 8 : 0);
  await client.writeRegisters(R.jobId, id);
  await client.writeRegisters(R.bytes, [Math.floor(program.length / 65536), program.length % 65536]);
  await client.writeRegister(R.command, 1);
  await waitFor(client, (d) => d[0] === S.receiving, "receiving");
  const blockBytes = 2 * R.windowWords;
  for (let k = 1, offset = 0; offset < program.length; k++, offset += blockBytes) {
    const chunk = program.subarray(offset, offset + blockBytes);
    const words = new Array(Math.ceil(chunk.length / 2)).fill(0);
    for (let i = 0; i < chunk.length; i++) words[i >> 1] |= chunk[i] << (i % 2 === 0 ? 8 : 0);
    await client.writeRegisters(R.window, words);
    await client.writeRegisters(R.number, [k, chunk.length]);
    await waitFor(client, (d) => d[3] === k, `ack of block ${k}`);
  }
  await waitFor(client, (d) => d[0] === S.loaded, "loaded");
  await client.writeRegister(R.command, 2);
  await waitFor(client, (d) => d[0] === S.done, "done");
  client.close(() => {});
  console.log("done");
}

main().then(() => process.exit(0), (e) => { console.log(`error: ${e.message || e}`); process.exit(1); });
