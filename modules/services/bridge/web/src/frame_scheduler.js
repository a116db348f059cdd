// When the page draws: on an animation frame asked for only when something
// may have changed (a message came, the view was turned, the pointer moved),
// at most every POLL_MS for what the run changes and at once for what a
// person does. A page that asks for every animation frame keeps the
// browser's compositor busy sixty times a second, on the run's cores when
// the browser draws in software.

const POLL_MS = 50;

export class FrameScheduler {
  // draw(nowMs) returns true when it left something to draw later (a drawing
  // not yet due): the scheduler then asks again at the next poll.
  constructor(draw) {
    this.draw = draw;
    this.woken = false;
    this.requested = false;
    setInterval(() => this.poll(), POLL_MS);
  }

  // Something changed; drawn at the next poll.
  wake() {
    this.woken = true;
  }

  // A person did something: drawn on the next animation frame.
  wakeNow() {
    this.woken = true;
    this.poll();
  }

  poll() {
    if (!this.woken || this.requested) return;
    this.woken = false;
    this.requested = true;
    requestAnimationFrame((now) => {
      this.requested = false;
      if (this.draw(now)) this.woken = true;
    });
  }
}
