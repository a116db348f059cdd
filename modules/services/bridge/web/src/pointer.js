// The pointer over the 3-D view: a label under it on hover (raycast once
// per animation frame at most), a click on the ground sends the robot there
// (goto), a shift-click on an object makes it look at it (look_at). A drag
// turns the view (OrbitControls) and is not a click.
import { hypothesisLabel } from "./hypothesis_layer.js";

const CLICK_SLOP_PX = 5;

export class Pointer {
  // layers: {objects, hypotheses, audio}; tooltip: an absolutely placed element.
  constructor(view, layers, controls, tooltip) {
    this.view = view;
    this.layers = layers;
    this.controls = controls;
    this.tooltip = tooltip;
    this.hover = null;   // the last pointermove, to be raycast on the next frame
    this.down = null;
    const canvas = view.renderer.domElement;
    canvas.addEventListener("pointermove", (event) => {
      this.hover = event;
      if (view.onInteraction) view.onInteraction();
    });
    canvas.addEventListener("pointerleave", () => ((this.hover = null), this.hide()));
    canvas.addEventListener("pointerdown", (event) => (this.down = { x: event.clientX, y: event.clientY }));
    canvas.addEventListener("pointerup", (event) => this.released(event));
  }

  pickables() {
    const { objects, hypotheses, audio } = this.layers;
    return [...hypotheses.pickables(), ...audio.pickables(), ...objects.pickables()];
  }

  // What is under the pointer: {text, object} or null.
  describe(event) {
    const hit = this.view.pick(this.view.pointerNdc(event), this.pickables());
    const { objects, hypotheses, audio } = this.layers;
    const hypothesis = hypotheses.hypothesisOfHit(hit);
    if (hypothesis) return { text: hypothesisLabel(hypothesis), object: objects.byId.get(hypothesis.object_id) };
    const percept = audio.perceptOfHit(hit);
    if (percept) return { text: `${percept.object_id}: heard as ${percept.acoustic_label} (${percept.activity})` };
    const object = objects.objectOfHit(hit);
    if (object) return { text: `${object.id}: ${object.label}${object.activity ? `, ${object.activity}` : ""}`, object };
    return null;
  }

  // Called from the animation frame.
  update() {
    if (!this.hover) return;
    const event = this.hover;
    this.hover = null;
    const found = this.describe(event);
    if (!found) return this.hide();
    this.tooltip.textContent = found.text;
    this.tooltip.style.left = `${event.clientX + 12}px`;
    this.tooltip.style.top = `${event.clientY + 12}px`;
    this.tooltip.hidden = false;
  }

  hide() {
    this.tooltip.hidden = true;
  }

  released(event) {
    if (!this.down || event.button !== 0) return;
    const moved = Math.hypot(event.clientX - this.down.x, event.clientY - this.down.y);
    this.down = null;
    if (moved > CLICK_SLOP_PX) return;
    if (event.shiftKey) {
      const found = this.describe(event);
      if (found && found.object) this.controls.lookAt(found.object.id);
      return;
    }
    const point = this.view.groundPoint(this.view.pointerNdc(event));
    if (point) this.controls.goto(Number(point.x.toFixed(2)), Number(point.y.toFixed(2)));
  }
}
