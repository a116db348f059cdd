// When the page draws: on an animation frame asked for only when something
// changed (a message came, the view was turned, the pointer moved) and is
// due to be drawn, at most every POLL_MS for what the run changes and at
// once for what a person does. A page that asks for an animation frame
// without drawing in it still has the browser update, commit and composite
// the page: at twenty frames a second, on the run's cores when the browser
// draws in software.

const POLL_MS = 50;

export class FrameScheduler {
  // draw(nowMs) draws what is due and returns true when it left something to
  // draw later; nextDueMs() is the earliest time (performance.now()) at which
  // something left waiting is due (Infinity: nothing is).
  constructor(draw, nextDueMs = () => 0) {
    this.draw = draw;
    this.nextDueMs = nextDueMs;
    this.woken = false;
    this.requested = false;
    setInterval(() => this.poll(), POLL_MS);
  }

  // Something changed; drawn at the first poll at which it is due.
  wake() {
    this.woken = true;
  }

  // A person did something: drawn on the next animation frame.
  wakeNow() {
    this.woken = true;
    this.requestFrame();
  }

  poll() {
    if (!this.woken || this.requested || performance.now() < this.nextDueMs()) return;
    this.requestFrame();
  }

  requestFrame() {
    if (this.requested) return;
    this.woken = false;
    this.requested = true;
    requestAnimationFrame((now) => {
      this.requested = false;
      if (this.draw(now)) this.woken = true;
    });
  }
}
