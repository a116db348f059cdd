// A stand-in for beft-bridge that the page test scripts: it serves the built
// page over HTTP and speaks the Foxglove WebSocket protocol v1 on the same
// port, sends what the test tells it to, and keeps what the page sends.
import { readFileSync, existsSync } from "node:fs";
import { createServer } from "node:http";
import { extname, join, normalize } from "node:path";
import { WebSocketServer } from "ws";

const TYPES = { ".html": "text/html", ".js": "text/javascript", ".css": "text/css", ".map": "application/json" };

export class FakeBridge {
  // topics: names to advertise; info: the serverInfo message's fields.
  constructor(webDir, topics, info) {
    this.webDir = webDir;
    this.channels = topics.map((topic, i) => ({ id: i + 1, topic, encoding: "json", schemaName: topic, schema: "{}", schemaEncoding: "jsonschema" }));
    this.info = info;
    this.subscriptions = new Map();  // channel id -> subscription id
    this.throttles = new Map();      // topic -> the throttleMs its subscription asked for (0: none)
    this.clientChannels = new Map(); // client channel id -> topic
    this.received = [];              // {topic, message} the page published
    this.sockets = new Set();
  }

  listen(port) {
    this.http = createServer((request, response) => this.serveFile(request, response));
    this.ws = new WebSocketServer({
      server: this.http,
      handleProtocols: (protocols) => (protocols.has("foxglove.websocket.v1") ? "foxglove.websocket.v1" : false),
    });
    this.ws.on("connection", (socket) => this.connected(socket));
    return new Promise((resolve) => this.http.listen(port, "127.0.0.1", resolve));
  }

  serveFile(request, response) {
    const name = request.url === "/" ? "index.html" : normalize(decodeURIComponent(request.url.split("?")[0])).replace(/^[/\\]+/, "");
    const path = join(this.webDir, name);
    if (name.includes("..") || !existsSync(path)) {
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, { "content-type": TYPES[extname(path)] || "application/octet-stream" });
    response.end(readFileSync(path));
  }

  connected(socket) {
    this.sockets.add(socket);
    socket.on("close", () => this.sockets.delete(socket));
    socket.on("message", (data, isBinary) => (isBinary ? this.clientData(data) : this.clientText(JSON.parse(data.toString()))));
    socket.send(JSON.stringify({ op: "serverInfo", name: "fake bridge", supportedEncodings: ["json"], ...this.info }));
    socket.send(JSON.stringify({ op: "advertise", channels: this.channels }));
  }

  clientText(message) {
    if (message.op === "subscribe")
      for (const s of message.subscriptions) {
        this.subscriptions.set(s.channelId, s.id);
        const channel = this.channels.find((c) => c.id === s.channelId);
        if (channel) this.throttles.set(channel.topic, s.throttleMs || 0);
      }
    if (message.op === "advertise") for (const c of message.channels) this.clientChannels.set(c.id, c.topic);
  }

  clientData(data) {
    if (data[0] !== 1) return;
    const topic = this.clientChannels.get(data.readUInt32LE(1));
    this.received.push({ topic, text: data.subarray(5).toString("utf8"), message: JSON.parse(data.subarray(5).toString("utf8")) });
  }

  subscribed(topic) {
    const channel = this.channels.find((c) => c.topic === topic);
    return channel !== undefined && this.subscriptions.has(channel.id);
  }

  publish(topic, message, receiveNs = 0n) {
    const channel = this.channels.find((c) => c.topic === topic);
    const subscription = channel && this.subscriptions.get(channel.id);
    if (subscription === undefined) return false;
    const payload = Buffer.from(JSON.stringify(message));
    const frame = Buffer.alloc(13 + payload.length);
    frame.writeUInt8(1, 0);
    frame.writeUInt32LE(subscription, 1);
    frame.writeBigUInt64LE(BigInt(receiveNs), 5);
    payload.copy(frame, 13);
    for (const socket of this.sockets) socket.send(frame);
    return true;
  }

  sendTime(ns) {
    const frame = Buffer.alloc(9);
    frame.writeUInt8(2, 0);
    frame.writeBigUInt64LE(BigInt(ns), 1);
    for (const socket of this.sockets) socket.send(frame);
  }

  close() {
    for (const socket of this.sockets) socket.terminate();
    this.ws.close();
    return new Promise((resolve) => this.http.close(resolve));
  }
}
