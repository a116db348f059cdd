// What a Foxglove client nobody here wrote (@foxglove/ws-protocol's
// FoxgloveClient over the `ws` package) sees of a beft-bridge: one connection,
// what it was told, and the messages of its subscriptions decoded as JSON.
"use strict";

const { FoxgloveClient } = require("@foxglove/ws-protocol");
const WebSocket = require("ws");

class Viewer {
  constructor(url) {
    this.url = url;
    this.channels = new Map();   // topic -> advertised channel
    this.byId = new Map();       // channel id -> channel
    this.subscriptions = new Map();  // subscription id -> topic
    this.messages = new Map();   // topic -> decoded JSON messages, oldest first
    this.statuses = [];
    this.times = [];
    this.serverInfo = null;
    this.closed = false;
  }

  open() {
    return new Promise((resolve, reject) => {
      const ws = new WebSocket(this.url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
      this.client = new FoxgloveClient({ ws });
      this.client.on("error", (error) => reject(error));
      this.client.on("close", () => { this.closed = true; });
      this.client.on("serverInfo", (info) => { this.serverInfo = info; });
      this.client.on("status", (status) => this.statuses.push(status));
      this.client.on("time", (time) => this.times.push(time.timestamp));
      this.client.on("advertise", (channels) => {
        for (const channel of channels) {
          this.channels.set(channel.topic, channel);
          this.byId.set(channel.id, channel);
        }
        resolve(this);
      });
      this.client.on("message", (event) => this.onMessage(event));
    });
  }

  onMessage(event) {
    const topic = this.subscriptions.get(event.subscriptionId);
    if (topic === undefined) throw new Error(`a message of subscription ${event.subscriptionId}, never made`);
    const text = new TextDecoder().decode(event.data);
    const list = this.messages.get(topic) || [];
    list.push({ json: JSON.parse(text), timestamp: event.timestamp });
    if (list.length > 50) list.shift();
    this.messages.set(topic, list);
  }

  subscribe(topic) {
    const channel = this.channels.get(topic);
    if (!channel) throw new Error(`${topic} was not advertised`);
    const id = this.client.subscribe(channel.id);
    this.subscriptions.set(id, topic);
    return id;
  }

  unsubscribe(id) {
    this.client.unsubscribe(id);
    this.subscriptions.delete(id);
  }

  latest(topic) {
    const list = this.messages.get(topic);
    return list && list.length ? list[list.length - 1].json : undefined;
  }

  // Publishes one JSON control on a topic it advertises once.
  publish(topic, body) {
    this.published = this.published || new Map();
    if (!this.published.has(topic))
      this.published.set(topic, this.client.advertise({ topic, encoding: "json", schemaName: topic }));
    this.client.sendMessage(this.published.get(topic), new TextEncoder().encode(JSON.stringify(body)));
  }

  close() { this.client.close(); }
}

// Resolves once `condition()` holds; rejects with `what` after `seconds`.
async function waitFor(what, seconds, condition) {
  const deadline = Date.now() + seconds * 1000;
  while (!condition()) {
    if (Date.now() > deadline) throw new Error(`timed out after ${seconds} s waiting for ${what}`);
    await new Promise((r) => setTimeout(r, 50));
  }
}

let failures = 0;
function check(condition, what) {
  console.log(`${condition ? "ok  " : "FAIL"} ${what}`);
  if (!condition) failures += 1;
}
function failed() { return failures; }

// What every bridge must advertise: each BEFT channel with its JSON Schema, and the Foxglove topics.
function checkAdvertised(viewer) {
  const info = viewer.serverInfo;
  check(info && info.name === "beft-bridge", "serverInfo names the bridge");
  check(info && info.capabilities.includes("clientPublish"), "serverInfo offers clientPublish");
  check(info && typeof info.sessionId === "string" && info.sessionId.length > 0, "serverInfo has a sessionId");
  check(info && info.metadata && typeof info.metadata.run === "string", "serverInfo's metadata names the run");
  const robot = viewer.channels.get("ROBOT_STATE");
  check(robot && robot.encoding === "json" && robot.schemaEncoding === "jsonschema", "ROBOT_STATE: json, jsonschema");
  let schema = {};
  try { schema = JSON.parse(robot.schema); } catch (e) { /* checked below */ }
  check(schema.type === "object" && schema.properties && schema.properties.x, "ROBOT_STATE's schema describes x");
  for (const [topic, name] of [["/scene", "foxglove.SceneUpdate"], ["/tf", "foxglove.FrameTransforms"],
                               ["/obstacle_map", "foxglove.Grid"], ["/camera/color", "foxglove.RawImage"],
                               ["/camera/depth", "foxglove.RawImage"], ["/log", "foxglove.Log"]]) {
    const channel = viewer.channels.get(topic);
    check(channel && channel.schemaName === name && JSON.parse(channel.schema).type === "object",
          `${topic} advertised as ${name} with its schema`);
  }
  check([...viewer.channels.keys()].every((topic) => !topic.includes("@")), "no topic carries a run id");
  check(viewer.channels.has("TASK_STACK") && viewer.channels.has("GT_OBJECTS"), "every BEFT channel is a topic");
}

module.exports = { Viewer, waitFor, check, failed, checkAdvertised };
