// Reads what the browser test compares the page with from a run's LCM log
// (lcm-logger's format): every event's channel and log time, and the
// robot's pose from ROBOT_STATE (lcmtypes/robot_state_t.lcm: a fingerprint,
// then utime, tick, x, y, yaw, big-endian).
import { readFileSync } from "node:fs";

const SYNC = 0xeda1da01;

// [{channel (without the run's "@id" suffix), utime (log time, us, BigInt), data (Buffer)}]
export function readLogEvents(path) {
  const bytes = readFileSync(path);
  const events = [];
  let at = 0;
  while (at + 28 <= bytes.length && bytes.readUInt32BE(at) === SYNC) {
    const utime = bytes.readBigInt64BE(at + 12);
    const channelLength = bytes.readInt32BE(at + 20);
    const dataLength = bytes.readInt32BE(at + 24);
    const end = at + 28 + channelLength + dataLength;
    if (channelLength < 0 || dataLength < 0 || end > bytes.length) break;  // a cut last event
    const channel = bytes.toString("latin1", at + 28, at + 28 + channelLength).split("@")[0];
    events.push({ channel, utime, data: bytes.subarray(at + 28 + channelLength, end) });
    at = end;
  }
  return events;
}

export function robotStates(events) {
  return events
    .filter((e) => e.channel === "ROBOT_STATE" && e.data.length >= 48)
    .map((e) => ({
      logUtime: e.utime,
      utime: e.data.readBigInt64BE(8),
      tick: Number(e.data.readBigInt64BE(16)),
      x: e.data.readDoubleBE(24),
      y: e.data.readDoubleBE(32),
      yaw: e.data.readDoubleBE(40),
    }));
}

// The robot state in force at log time `utime`: the last one logged at or before it.
export function robotStateAt(states, utime) {
  let found = null;
  for (const state of states) if (state.logUtime <= utime) found = state;
  return found;
}
