package beft;

import java.net.InetAddress;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * An expert's heartbeat_t on HEARTBEAT every period, from a thread of its
 * own, as lib/expert/heartbeat_thread.cpp sends them: MATLAB and Octave run
 * the expert's code on one thread, and a long firing must go on beating.
 * The expert says what it is doing with update(); beatNow() answers an
 * arbiter that waits for heartbeats (at most one every 50 ms). They begin
 * "starting": a restarted expert replays the run's history first.
 */
public final class Heartbeats {
  private static final long MIN_GAP_NS = 50_000_000L;

  private final BridgeSocket socket;
  private final double channelId;
  private final String process;
  private final String host = hostName();
  private final ScheduledExecutorService thread;
  private volatile long lastFiringId = -1;
  private volatile String state;
  private long lastBeatNs = 0;

  public Heartbeats(BridgeSocket socket, double channelId, String process, double periodSeconds, String state) {
    this.socket = socket;
    this.state = state;
    this.channelId = channelId;
    this.process = process;
    thread = Executors.newSingleThreadScheduledExecutor(runnable -> {
      Thread beating = new Thread(runnable, "heartbeats");
      beating.setDaemon(true);
      return beating;
    });
    long periodUs = Math.max(1L, (long) (periodSeconds * 1e6));
    thread.scheduleAtFixedRate(this::beat, 0, periodUs, TimeUnit.MICROSECONDS);
  }

  /** The last firing finished (-1: none) and "idle", "firing" or "waiting". */
  public void update(double lastFiringId, String state) {
    this.lastFiringId = (long) lastFiringId;
    this.state = state;
  }

  public void beatNow() {
    thread.execute(() -> {
      if (System.nanoTime() - lastBeatNs >= MIN_GAP_NS) beat();
    });
  }

  public void stop() {
    thread.shutdownNow();
  }

  /** This process's id: the JVM runs inside MATLAB's or Octave's process. */
  public static double pid() {
    return ProcessHandle.current().pid();
  }

  public static String hostName() {
    try {
      return InetAddress.getLocalHost().getHostName();
    } catch (Exception unresolved) {
      String name = System.getenv("HOSTNAME");
      return name != null ? name : "localhost";
    }
  }

  private void beat() {
    lastBeatNs = System.nanoTime();
    long utime = System.currentTimeMillis() * 1000L;
    String json = "{\"utime\":" + utime + ",\"process\":" + quoted(process) + ",\"pid\":" + (long) pid()
                  + ",\"host\":" + quoted(host) + ",\"last_firing_id\":" + lastFiringId + ",\"state\":"
                  + quoted(state) + "}";
    try {
      socket.publish(channelId, json);
    } catch (Exception gone) {
      stop();  // the expert's loop sees the socket closed and exits
    }
  }

  static String quoted(String text) {
    StringBuilder out = new StringBuilder("\"");
    for (char c : text.toCharArray()) {
      if (c == '"' || c == '\\') out.append('\\').append(c);
      else if (c < 0x20) out.append(String.format("\\u%04x", (int) c));
      else out.append(c);
    }
    return out.append('"').toString();
  }
}
