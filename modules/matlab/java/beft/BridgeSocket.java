package beft;

import java.io.ByteArrayOutputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;

/**
 * The client side of a Foxglove WebSocket (protocol v1) connection to the
 * run's bridge, for MATLAB and Octave, which call into Java but cannot be
 * called back: frames arrive on the JDK's threads and wait in a queue that
 * the expert polls with next(timeoutMs); after it, kind(), text(), hex() and
 * subscription() describe the frame taken. Every argument and result is a
 * double, a String or a boolean, which both convert the same way.
 */
public final class BridgeSocket implements WebSocket.Listener {
  public static final String SUBPROTOCOL = "foxglove.websocket.v1";
  private static final byte SERVER_MESSAGE_DATA = 1;
  private static final byte CLIENT_MESSAGE_PUBLISH = 1;
  private static final int MESSAGE_DATA_HEADER = 13;  // opcode, subscription id, receive time

  private static final class Frame {
    final String kind;          // "text", "data" (message data) or "closed"
    final long subscription;    // data: the subscription id
    final JsonNumbers json;     // text, data: the JSON with its exact numbers
    final String reason;        // closed: why

    Frame(String kind, long subscription, JsonNumbers json, String reason) {
      this.kind = kind;
      this.subscription = subscription;
      this.json = json;
      this.reason = reason;
    }
  }

  private static final Frame NOTHING = new Frame("", 0, null, "");

  private final LinkedBlockingQueue<Frame> frames = new LinkedBlockingQueue<>();
  private final StringBuilder textParts = new StringBuilder();
  private final ByteArrayOutputStream binaryParts = new ByteArrayOutputStream();
  private final Object sendLock = new Object();
  private final List<String> history = new ArrayList<>();  // guarded by itself
  private final WebSocket socket;
  private volatile Frame closed = null;
  private volatile long filteredSubscription = -1;
  private volatile Pattern keep = null;
  private Frame current = NOTHING;

  /** Connects (throws when the bridge cannot be reached within the time-out). */
  public BridgeSocket(String url, double timeoutSeconds) throws Exception {
    Duration timeout = Duration.ofMillis((long) (timeoutSeconds * 1000));
    socket = HttpClient.newHttpClient().newWebSocketBuilder().subprotocols(SUBPROTOCOL).connectTimeout(timeout)
                 .buildAsync(URI.create(url), this).get((long) (timeoutSeconds * 1000), TimeUnit.MILLISECONDS);
    if (!SUBPROTOCOL.equals(socket.getSubprotocol())) {
      socket.abort();
      throw new IllegalStateException(url + " does not speak " + SUBPROTOCOL);
    }
  }

  /** The next frame's kind, waiting up to timeoutMs: "text", "data", "closed", or "" (none came). */
  public String next(double timeoutMs) throws InterruptedException {
    Frame frame = timeoutMs > 0 ? frames.poll((long) timeoutMs, TimeUnit.MILLISECONDS) : frames.poll();
    if (frame == null && closed != null) frame = closed;  // said again on every call once closed
    current = frame == null ? NOTHING : frame;
    return current.kind;
  }

  /** The frame's JSON with its numbers numbered (JsonNumbers); closed: the reason. */
  public String text() { return current.json == null ? current.reason : current.json.text(); }

  public String hex() { return current.json == null ? "" : current.json.hex(); }

  public double subscription() { return current.subscription; }

  /**
   * The run's history the bridge sent a resuming expert (its beftHistory
   * messages, which come before it accepts the expert), as one JSON array,
   * a FIRE re-sent only once; afterwards text() and hex() give it. Read in
   * one piece: one message at a time, a long history took Octave longer
   * than the arbiter waits for a restarted expert's DONE.
   */
  public String takeHistory() {
    String joined;
    synchronized (history) {
      joined = "[" + String.join(",", history) + "]";
      history.clear();
    }
    current = new Frame("history", 0, new JsonNumbers(joined), "");
    return current.kind;
  }

  /**
   * Drops, before they are queued, the messages on one subscription whose
   * member KEY is not the string VALUE: FIRE carries every expert's tokens,
   * each re-sent every few milliseconds until its DONE, and an expert
   * written in MATLAB or Octave would spend its time reading other
   * experts' tokens.
   */
  public void keepOnly(double subscription, String key, String value) {
    keep = Pattern.compile("\"" + Pattern.quote(key) + "\"\\s*:\\s*\"" + Pattern.quote(value) + "\"");
    filteredSubscription = (long) subscription;
  }

  public void sendText(String text) throws Exception {
    synchronized (sendLock) {
      socket.sendText(text, true).get();  // one send at a time: the JDK refuses overlapping ones
    }
  }

  /** A client message publish frame: opcode, the client channel id, the JSON as UTF-8. */
  public void publish(double channelId, String json) throws Exception {
    byte[] payload = json.getBytes(StandardCharsets.UTF_8);
    // The id is written little-endian by hand: the JDK's frame masking
    // reads the buffer in its byte order and scrambles a little-endian one.
    ByteBuffer frame = ByteBuffer.allocate(5 + payload.length);
    frame.put(CLIENT_MESSAGE_PUBLISH).putInt(Integer.reverseBytes((int) (long) channelId)).put(payload).flip();
    synchronized (sendLock) {
      socket.sendBinary(frame, true).get();
    }
  }

  public boolean isClosed() { return closed != null; }

  public void close() {
    if (closed == null) socket.sendClose(WebSocket.NORMAL_CLOSURE, "").orTimeout(1, TimeUnit.SECONDS);
  }

  @Override
  public void onOpen(WebSocket webSocket) {
    webSocket.request(1);
  }

  @Override
  public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
    textParts.append(data);
    if (last) {
      String text = textParts.toString();
      textParts.setLength(0);
      if (HistoryText.isHistory(text)) {
        synchronized (history) {
          if (history.isEmpty() || !history.get(history.size() - 1).equals(text)) history.add(text);
        }
      } else {
        frames.add(new Frame("text", 0, new JsonNumbers(text), ""));
      }
    }
    webSocket.request(1);
    return null;
  }

  @Override
  public CompletionStage<?> onBinary(WebSocket webSocket, ByteBuffer data, boolean last) {
    byte[] part = new byte[data.remaining()];
    data.get(part);
    binaryParts.write(part, 0, part.length);
    if (last) {
      onMessageData(binaryParts.toByteArray());
      binaryParts.reset();
    }
    webSocket.request(1);
    return null;
  }

  // Message data (opcode 1): subscription id (uint32 LE), receive time
  // (uint64 LE), the message's JSON. Other binary opcodes are not for experts.
  private void onMessageData(byte[] bytes) {
    if (bytes.length < MESSAGE_DATA_HEADER || bytes[0] != SERVER_MESSAGE_DATA) return;
    long subscription = ByteBuffer.wrap(bytes, 1, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xffffffffL;
    String json = new String(bytes, MESSAGE_DATA_HEADER, bytes.length - MESSAGE_DATA_HEADER, StandardCharsets.UTF_8);
    Pattern kept = keep;
    if (subscription == filteredSubscription && kept != null && !kept.matcher(json).find()) return;
    frames.add(new Frame("data", subscription, new JsonNumbers(json), ""));
  }

  @Override
  public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
    markClosed("the bridge closed the connection (" + statusCode + (reason.isEmpty() ? "" : ", " + reason) + ")");
    return null;
  }

  @Override
  public void onError(WebSocket webSocket, Throwable error) {
    markClosed("the connection failed: " + error);
  }

  private void markClosed(String reason) {
    Frame frame = new Frame("closed", 0, null, reason);
    closed = frame;
    frames.add(frame);
  }
}
