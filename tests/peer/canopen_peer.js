#!/usr/bin/env node
// An independent CANopen device for testing the CutCell master: the npm package `canopen`
// (a CiA 301 stack written by someone else: SDO server, NMT, heartbeat, EMCY, PDOs) bridged to
// Qt's virtualcan bus. Its object dictionary holds the CiA 402 objects the master maps, behind a
// toy power state machine, so the master's whole start-up, PDO mapping and enabling run
// against it.
//
// virtualcan's protocol (Qt's plugins/canbus/virtualcan/virtualcanbackend.cpp): ASCII lines
// over TCP 127.0.0.1:PORT. A client sends "connect:can0\n" once, then one line per frame,
// "can0:<id decimal>#<flags>#<payload hex>\n"; the server sends every other client's frames on
// that channel as "<id decimal>#<flags>#<payload hex>\n". Flags: R remote, X extended, F FD,
// B bit-rate switch, E error state, L local echo (none of them used here).
//
// usage: node canopen_peer.js --port 35468 --channel can0 --id 10
// stdin (one command per line):  emcy 0x2310 | heartbeat off | position 12345 | dump | quit
// stdout (one event per line):   ready | nmt <STATE> | heartbeat-timeout <id> |
//                                controlword 0x000F | od {json} | error <text>
'use strict';

const net = require('net');
const readline = require('readline');
const { Device, DataType, ObjectType, AccessType, NmtState } = require('canopen');

function arg(name, fallback) {
    const i = process.argv.indexOf(name);
    return i > 0 && i + 1 < process.argv.length ? process.argv[i + 1] : fallback;
}
const port = Number(arg('--port', '35468'));
const channel = arg('--channel', 'can0');
const id = Number(arg('--id', '10'));
const say = (line) => process.stdout.write(line + '\n');

// ---- object dictionary ------------------------------------------------------------------
const device = new Device({ id });
const eds = device.eds;
function variable(index, name, dataType, value) {
    const existing = eds.getEntry(index); // the stack's own mandatory entries (0x1000, ...)
    if (existing) {
        existing.defaultValue = value; // an NMT reset restores the defaults
        existing.value = value;
        return existing;
    }
    const e = eds.addEntry(index, {
        parameterName: name,
        objectType: ObjectType.VAR,
        dataType,
        accessType: AccessType.READ_WRITE,
        defaultValue: value,
    });
    e.value = value;
    return e;
}
variable(0x1000, 'Device type', DataType.UNSIGNED32, 0x00020192); // CiA 402 servo drive
variable(0x1006, 'Communication cycle period', DataType.UNSIGNED32, 0);
// The SYNC counter's overflow (CiA 301): the master writes it to every node it uses.
if (!eds.getEntry(0x1019))
    variable(0x1019, 'Synchronous counter overflow value', DataType.UNSIGNED8, 0);
variable(0x1017, 'Producer heartbeat time', DataType.UNSIGNED16, 0);
if (!eds.getEntry(0x1016))
    eds.addEntry(0x1016, { parameterName: 'Consumer heartbeat time', objectType: ObjectType.ARRAY });
eds.addSubEntry(0x1016, 1, {
    parameterName: 'Consumer 1',
    dataType: DataType.UNSIGNED32,
    accessType: AccessType.READ_WRITE,
    defaultValue: 0,
});
eds.addSdoServerParameter(0, 0x580 + id, 0x600 + id);
eds.setEmcyCobId(0x80 + id, { saveDefault: true }); // survives a reset
eds.setSyncCobId(0x80, { saveDefault: true }); // without 0x1005 the stack ignores SYNC
const abortOption = variable(0x6007, 'Abort connection option code', DataType.INTEGER16, 1);
const controlword = variable(0x6040, 'Controlword', DataType.UNSIGNED16, 0);
const statusword = variable(0x6041, 'Statusword', DataType.UNSIGNED16, 0x0240);
const mode = variable(0x6060, 'Modes of operation', DataType.INTEGER8, 0);
const actual = variable(0x6064, 'Position actual value', DataType.INTEGER32, 0);
variable(0x6077, 'Torque actual value', DataType.INTEGER16, 0);
const target = variable(0x607A, 'Target position', DataType.INTEGER32, 0);
// PDOs as a factory would ship them; the master must remap them: TPDO1 starts with its
// objects in the wrong order and event-driven, so a master that does not map it reads garbage.
eds.addReceivePdo({ cobId: 0x200 + id, transmissionType: 254, dataObjects: [controlword, target] });
eds.addReceivePdo({ cobId: 0x300 + id, transmissionType: 254, dataObjects: [controlword] });
eds.addTransmitPdo({
    cobId: 0x180 + id,
    transmissionType: 254,
    dataObjects: [eds.getEntry(0x6077), actual, statusword],
});

// ---- toy CiA 402 power state machine (enough for the master's enabling) -----------------
const SW = { disabled: 0x0240, ready: 0x0221, switchedOn: 0x0223, enabled: 0x0227 };
// A received PDO writes the objects' raw bytes and emits only the Pdo module's 'pdo' event
// (no per-object 'update'): act on both.
function onControlword(obj) {
    const cw = obj.value & 0x8F;
    const sw = statusword.value & 0x6F;
    let next = statusword.value;
    if ((cw & 0x02) === 0) next = SW.disabled; // disable voltage
    else if ((cw & 0x87) === 0x06) next = SW.ready; // shutdown
    else if ((cw & 0x8F) === 0x07 && sw !== 0x40) next = SW.switchedOn; // switch on
    else if ((cw & 0x8F) === 0x0F && (sw === 0x23 || sw === 0x27)) next = SW.enabled;
    else if ((cw & 0x86) === 0x02) next = SW.disabled; // quick stop (then disabled)
    if (next !== statusword.value) statusword.value = next;
    if (obj.value !== lastControlword) {
        lastControlword = obj.value;
        say('controlword 0x' + obj.value.toString(16).padStart(4, '0').toUpperCase());
    }
}
let lastControlword = null;
function onTarget(obj) {
    if (statusword.value === SW.enabled) actual.value = obj.value;
}
controlword.addListener('update', onControlword);
target.addListener('update', onTarget);
device.pdo.addListener('pdo', (pdo) => {
    for (const obj of pdo.dataObjects) {
        if (obj.index === 0x6040) onControlword(obj);
        if (obj.index === 0x607A) onTarget(obj);
    }
});

// ---- virtualcan bridge --------------------------------------------------------------------
const socket = net.connect({ host: '127.0.0.1', port }, () => {
    socket.setNoDelay(true);
    socket.write(`connect:${channel}\n`);
    device.start();
    bootUp();
    say('ready');
});
socket.on('error', (e) => {
    say('error ' + e.message);
    process.exit(2);
});
socket.on('close', () => process.exit(0));
let pending = '';
socket.on('data', (chunk) => {
    pending += chunk.toString('latin1');
    let nl;
    while ((nl = pending.indexOf('\n')) >= 0) {
        const line = pending.slice(0, nl).trim();
        pending = pending.slice(nl + 1);
        const parts = line.split('#');
        if (parts.length !== 3) continue;
        if (/[RXF]/.test(parts[1])) continue; // remote, extended or FD: not CANopen frames here
        device.receive({ id: Number(parts[0]), data: Buffer.from(parts[2], 'hex') });
    }
});
function sendFrame({ id: frameId, data }) {
    if (!socket.writable) return;
    socket.write(`${channel}:${frameId}##${Buffer.from(data).toString('hex')}\n`);
}
device.addListener('message', sendFrame);

// canopen 6.2.1 sends no boot-up message after a reset (CiA 301 requires one: heartbeat
// COB-ID, state 0x00), so the bridge sends it when the stack comes back to pre-operational.
function bootUp() {
    sendFrame({ id: 0x700 + id, data: Buffer.from([0x00]) });
}
let lastState = null;
device.nmt.addListener('changeState', (state) => {
    const name = Object.keys(NmtState).find((k) => NmtState[k] === state) || String(state);
    if (state === NmtState.PRE_OPERATIONAL && lastState === NmtState.INITIALIZING) bootUp();
    lastState = state;
    say('nmt ' + name);
});
device.nmt.addListener('timeout', (deviceId) => say('heartbeat-timeout ' + deviceId));

// ---- commands from the test -------------------------------------------------------------
function dump() {
    const consumer = eds.getSubEntry(0x1016, 1);
    const map = (index) => {
        const e = eds.getEntry(index);
        const out = [];
        for (let s = 1; s <= e[0].value; ++s) out.push(e[s].value);
        return out;
    };
    say('od ' + JSON.stringify({
        cycle_period_us: eds.getEntry(0x1006).value,
        mode: mode.value,
        producer_heartbeat_ms: eds.getEntry(0x1017).value,
        consumer_heartbeat: consumer ? consumer.value : 0,
        abort_connection_option: abortOption.value,
        tpdo1_cob_id: eds.getSubEntry(0x1800, 1).value,
        tpdo1_type: eds.getSubEntry(0x1800, 2).value,
        tpdo1_map: map(0x1A00),
        rpdo1_map: map(0x1600),
        rpdo2_map: map(0x1601),
        statusword: statusword.value,
    }));
}
readline.createInterface({ input: process.stdin }).on('line', (line) => {
    const [cmd, value] = line.trim().split(/\s+/);
    try {
        if (cmd === 'emcy') device.emcy.write(Number(value));
        else if (cmd === 'heartbeat' && value === 'off') eds.getEntry(0x1017).value = 0;
        else if (cmd === 'position') actual.value = Number(value);
        else if (cmd === 'dump') dump();
        else if (cmd === 'quit') process.exit(0);
        else say('error unknown command: ' + line);
    }
    catch (e) {
        say('error ' + e.message);
    }
});
