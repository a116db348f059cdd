"""The client side of the Foxglove WebSocket protocol v1 (foxglove/ws-protocol
docs/spec.md), without the socket: the client's text messages, its binary
publish frame, and the server's frames read. The bridge speaks the server
side (lib/foxglove/protocol.hpp)."""

import json
import struct

SUBPROTOCOL = "foxglove.websocket.v1"
SERVER_OP_MESSAGE_DATA = 1
CLIENT_OP_MESSAGE_PUBLISH = 1
STATUS_INFO, STATUS_WARNING, STATUS_ERROR = 0, 1, 2


def advertise(channels):
    """channels: [(id, topic, schema_name)], all with encoding json."""
    return json.dumps({"op": "advertise", "channels": [
        {"id": cid, "topic": topic, "encoding": "json", "schemaName": schema} for cid, topic, schema in channels]})


def subscribe(subscriptions):
    """subscriptions: [(subscription id, server channel id)]."""
    return json.dumps({"op": "subscribe", "subscriptions": [
        {"id": sid, "channelId": cid} for sid, cid in subscriptions]})


def publish_frame(client_channel_id, payload_text):
    return struct.pack("<BI", CLIENT_OP_MESSAGE_PUBLISH, client_channel_id) + payload_text.encode("utf-8")


def parse_message_data(frame):
    """A binary server frame: (subscription id, receive time [ns], payload
    text), or None for any other opcode or a frame too short."""
    if len(frame) < 13 or frame[0] != SERVER_OP_MESSAGE_DATA:
        return None
    subscription_id, receive_time = struct.unpack_from("<IQ", frame, 1)
    return subscription_id, receive_time, bytes(frame[13:]).decode("utf-8")


def parse_text(text):
    """A server text message as a dict with "op", or None when it is not one."""
    try:
        message = json.loads(text)
    except ValueError:
        return None
    return message if isinstance(message, dict) and isinstance(message.get("op"), str) else None
