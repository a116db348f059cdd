// A client of the Foxglove WebSocket protocol v1 (foxglove/ws-protocol,
// docs/spec.md), as much of it as the viewer needs: server info, channel
// advertisements, subscriptions, message data and time frames from the
// server; client channels and client message data towards it.

export const SUBPROTOCOL = "foxglove.websocket.v1";

const OP_MESSAGE_DATA = 1;
const OP_TIME = 2;
const RECONNECT_MS = 1000;

export class FoxgloveClient {
  // handlers: {onOpen, onClose, onServerInfo(info), onAdvertise(channels),
  //            onMessage(topic, payloadText, receiveNs), onTime(ns), onStatus(msg)}
  constructor(url, handlers) {
    this.url = url;
    this.handlers = handlers;
    this.channelsById = new Map();   // server channel id -> channel
    this.subscriptions = new Map();  // subscription id -> channel
    this.wantedTopics = new Map();   // topic -> throttleMs (0: every message)
    this.clientChannels = new Map(); // topic -> client channel id
    this.nextSubscriptionId = 1;
    this.nextClientChannelId = 1;
    this.decoder = new TextDecoder();
    this.encoder = new TextEncoder();
    this.socket = null;
    this.connect();
  }

  connect() {
    const socket = new WebSocket(this.url, [SUBPROTOCOL]);
    socket.binaryType = "arraybuffer";
    socket.onopen = () => this.handlers.onOpen?.();
    socket.onclose = () => this.lost();
    socket.onerror = () => {};  // onclose follows
    socket.onmessage = (event) => this.received(event.data);
    this.socket = socket;
  }

  // The server went away: forget its channels and try again.
  lost() {
    this.channelsById.clear();
    this.subscriptions.clear();
    this.clientChannels.clear();
    this.handlers.onClose?.();
    setTimeout(() => this.connect(), RECONNECT_MS);
  }

  // Topics to subscribe whenever the server advertises them. With
  // throttleMs (BEFT's extension of subscribe, after rosbridge's
  // throttle_rate) the bridge sends at most one message per throttleMs, the
  // newest: for topics whose message holds the whole state.
  want(topics, throttleMs = 0) {
    for (const topic of topics) this.wantedTopics.set(topic, throttleMs);
  }

  received(data) {
    if (typeof data === "string") this.receivedText(JSON.parse(data));
    else this.receivedBinary(new DataView(data));
  }

  receivedText(message) {
    switch (message.op) {
      case "serverInfo":
        this.handlers.onServerInfo?.(message);
        break;
      case "advertise":
        this.advertised(message.channels || []);
        break;
      case "unadvertise":
        this.unadvertised(message.channelIds || []);
        break;
      case "status":
        this.handlers.onStatus?.(message);
        break;
      default:
        break;
    }
  }

  advertised(channels) {
    const subscribe = [];
    for (const channel of channels) {
      this.channelsById.set(channel.id, channel);
      if (!this.wantedTopics.has(channel.topic)) continue;
      const id = this.nextSubscriptionId++;
      this.subscriptions.set(id, channel);
      const throttleMs = this.wantedTopics.get(channel.topic);
      subscribe.push(throttleMs > 0 ? { id, channelId: channel.id, throttleMs } : { id, channelId: channel.id });
    }
    if (subscribe.length) this.sendJson({ op: "subscribe", subscriptions: subscribe });
    this.handlers.onAdvertise?.(channels);
  }

  unadvertised(ids) {
    const gone = new Set(ids);
    for (const [subscriptionId, channel] of this.subscriptions)
      if (gone.has(channel.id)) this.subscriptions.delete(subscriptionId);
    for (const id of ids) this.channelsById.delete(id);
  }

  receivedBinary(view) {
    const opcode = view.getUint8(0);
    if (opcode === OP_MESSAGE_DATA) {
      const channel = this.subscriptions.get(view.getUint32(1, true));
      if (!channel) return;
      const receiveNs = view.getBigUint64(5, true);
      const payload = new Uint8Array(view.buffer, view.byteOffset + 13, view.byteLength - 13);
      this.handlers.onMessage?.(channel.topic, this.decoder.decode(payload), receiveNs);
    } else if (opcode === OP_TIME) {
      this.handlers.onTime?.(view.getBigUint64(1, true));
    }
  }

  // Publishes `message` (an object, or JSON text already written) on a client
  // channel of `topic`, advertising the channel first if needed (the server
  // must have clientPublish).
  publish(topic, message) {
    if (!this.socket || this.socket.readyState !== WebSocket.OPEN) return false;
    let id = this.clientChannels.get(topic);
    if (id === undefined) {
      id = this.nextClientChannelId++;
      this.clientChannels.set(topic, id);
      this.sendJson({ op: "advertise", channels: [{ id, topic, encoding: "json", schemaName: topic }] });
    }
    const text = typeof message === "string" ? message : JSON.stringify(message);
    const payload = this.encoder.encode(text);
    const frame = new Uint8Array(5 + payload.length);
    const view = new DataView(frame.buffer);
    view.setUint8(0, OP_MESSAGE_DATA);
    view.setUint32(1, id, true);
    frame.set(payload, 5);
    this.socket.send(frame);
    return true;
  }

  sendJson(message) {
    if (this.socket && this.socket.readyState === WebSocket.OPEN) this.socket.send(JSON.stringify(message));
  }
}
