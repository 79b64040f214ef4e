#!/usr/bin/env node
// An independent Sparkplug B host for the CutCell tests: the MQTT client and the payload
// decoder are written by others (npm `mqtt` and `sparkplug-payload`, pinned by
// package-lock.json), so the edge node's bytes are judged by a reader that shares no code with
// it. It connects over TLS (the broker's certificate checked against --ca), subscribes to
// spBv1.0/<group>/# and prints one JSON line per message on stdout:
//   {"topic":..., "kind":"NBIRTH", "edge":"cell-1", "seq":0, "timestamp":..., "bdSeq":3,
//    "metrics":[{"name":..., "alias":..., "type":"Double", "value":..., "historical":false}]}
// Lines {"event":"subscribed"}, {"event":"sent",...} and {"event":"error",...} tell its own state.
// With --send it publishes NCMDs to --edge (after subscribing, when --listen is given too):
//   --send rebirth | feed-hold | clear-queue | queue-job=@FILE | queue-job=TEXT
//   --send "metric=NAME:TYPE:VALUE"   (any metric, e.g. "Node Control/Start:Boolean:true")
// Without --listen it exits once the NCMDs are sent.
// The password comes from --password or the environment variable SPARKPLUG_PASSWORD.
'use strict';

const fs = require('fs');
const mqtt = require('mqtt');
const sparkplug = require('sparkplug-payload').get('spBv1.0');

function usage(message) {
  process.stderr.write(`sparkplug_listen: ${message}\n`);
  process.exit(64);
}

function parseArgs(argv) {
  const a = { port: 8883, sends: [], listen: false, reconnectMs: 200, clean: true };
  for (let i = 0; i < argv.length; ++i) {
    const key = argv[i];
    const next = () => {
      if (i + 1 >= argv.length) usage(`${key} needs a value`);
      return argv[++i];
    };
    switch (key) {
      case '--host': a.host = next(); break;
      case '--port': a.port = Number(next()); break;
      case '--ca': a.ca = next(); break;
      case '--user': a.user = next(); break;
      case '--password': a.password = next(); break;
      case '--group': a.group = next(); break;
      case '--edge': a.edge = next(); break;
      case '--send': a.sends.push(next()); break;
      case '--listen': a.listen = true; break;
      case '--client-id': a.clientId = next(); break;
      case '--persistent': a.clean = false; break; // keep the session (and its queue) over a
                                                   // reconnection
      case '--reconnect-ms': a.reconnectMs = Number(next()); break;
      default: usage(`unknown option ${key}`);
    }
  }
  if (!a.host || !a.ca || !a.group) usage('--host, --ca and --group are required');
  if (a.sends.length && !a.edge) usage('--send needs --edge');
  if (a.password === undefined) a.password = process.env.SPARKPLUG_PASSWORD;
  return a;
}

// Longs arrive as Long objects; every value CutCell publishes fits a double exactly.
function plain(v) {
  if (v !== null && typeof v === 'object' && typeof v.toNumber === 'function') return v.toNumber();
  return v;
}

function describe(topic, bytes) {
  const parts = topic.split('/');
  const line = { topic, kind: parts[2], edge: parts[3] };
  try {
    const p = sparkplug.decodePayload(bytes);
    line.seq = p.seq === undefined ? null : plain(p.seq);
    line.timestamp = p.timestamp === undefined ? null : plain(p.timestamp);
    line.metrics = (p.metrics || []).map((m) => ({
      name: m.name === undefined ? null : m.name,
      alias: m.alias === undefined ? null : plain(m.alias),
      type: m.type,
      value: plain(m.value),
      historical: m.isHistorical === true,
      properties: m.properties
        ? Object.fromEntries(Object.entries(m.properties).map(([k, v]) => [k, plain(v.value)]))
        : undefined,
    }));
    const bd = line.metrics.find((m) => m.name === 'bdSeq');
    line.bdSeq = bd ? bd.value : null;
  } catch (e) {
    line.error = `cannot decode: ${e.message}`;
  }
  return line;
}

// One NCMD metric from a --send argument.
function commandMetric(spec) {
  const eq = spec.indexOf('=');
  const kind = eq < 0 ? spec : spec.slice(0, eq);
  const arg = eq < 0 ? '' : spec.slice(eq + 1);
  switch (kind) {
    case 'rebirth': return { name: 'Node Control/Rebirth', type: 'Boolean', value: true };
    case 'feed-hold': return { name: 'Node Control/Feed Hold', type: 'Boolean', value: true };
    case 'clear-queue': return { name: 'Node Control/Clear Queue', type: 'Boolean', value: true };
    case 'queue-job': {
      const text = arg.startsWith('@') ? fs.readFileSync(arg.slice(1), 'utf8') : arg;
      return { name: 'Node Control/Queue Job', type: 'String', value: text };
    }
    case 'metric': {
      const [name, type, value] = arg.split(':');
      const v = type === 'Boolean' ? value === 'true' : type === 'String' ? value : Number(value);
      return { name, type, value: v };
    }
    default: usage(`--send ${spec}: not rebirth, feed-hold, clear-queue, queue-job=..., metric=...`);
  }
  return null;
}

function main() {
  const a = parseArgs(process.argv.slice(2));
  const out = (o) => process.stdout.write(`${JSON.stringify(o)}\n`);
  const client = mqtt.connect({
    protocol: 'mqtts',
    host: a.host,
    port: a.port,
    ca: fs.readFileSync(a.ca),
    rejectUnauthorized: true,
    username: a.user,
    password: a.password,
    clientId: a.clientId || `sparkplug-listen-${process.pid}`,
    clean: a.clean,
    protocolVersion: 4,
    reconnectPeriod: a.reconnectMs,
  });
  let sent = false;
  const sendAll = () => {
    if (sent || !a.sends.length) return;
    sent = true;
    const topic = `spBv1.0/${a.group}/NCMD/${a.edge}`;
    const payload = sparkplug.encodePayload({
      timestamp: Date.now(),
      metrics: a.sends.map(commandMetric),
    });
    client.publish(topic, payload, { qos: 1 }, (err) => {
      out(err ? { event: 'error', message: err.message } : { event: 'sent', topic, count: a.sends.length });
      if (!a.listen) client.end(false, () => process.exit(err ? 1 : 0));
    });
  };
  client.on('connect', () => {
    if (!a.listen) return sendAll();
    client.subscribe(`spBv1.0/${a.group}/#`, { qos: 1 }, (err) => {
      if (err) return out({ event: 'error', message: err.message });
      out({ event: 'subscribed' });
      sendAll();
    });
  });
  client.on('message', (topic, bytes) => out(describe(topic, bytes)));
  client.on('error', (e) => out({ event: 'error', message: e.message }));
  client.on('offline', () => out({ event: 'offline' }));
  process.stdin.on('end', () => client.end(true, () => process.exit(0)));
  process.on('SIGTERM', () => client.end(true, () => process.exit(0)));
}

main();
