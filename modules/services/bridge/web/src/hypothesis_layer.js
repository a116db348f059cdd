// Every hypothesis (HYPOTHESES at keyframes, HYPOTHESIS_CHANGES every tick)
// as a marker coloured by its state; its label shows on hover only, so that
// hundreds stay readable.
import * as THREE from "three";
import { InstancedSet } from "./instanced_set.js";

// State -> colour, also used by the legend.
export const HYPOTHESIS_STATES = [
  { name: "verified", colour: 0x30d050 },
  { name: "falsified", colour: 0xe040e0 },
  { name: "seen and heard", colour: 0x40d0ff },
  { name: "seen", colour: 0x4080ff },
  { name: "heard", colour: 0xffa020 },
  { name: "unperceived", colour: 0x909090 },
];
const colourOf = new Map(HYPOTHESIS_STATES.map((s) => [s.name, s.colour]));

export function hypothesisState(h) {
  if (h.verified) return "verified";
  if (h.falsified) return "falsified";
  if (h.seen && h.heard) return "seen and heard";
  if (h.seen) return "seen";
  if (h.heard) return "heard";
  return "unperceived";
}

export function hypothesisLabel(h) {
  const confidence = Number.isFinite(h.confidence) ? ` ${(100 * h.confidence).toFixed(0)} %` : "";
  const senses = [h.seen_as ? `seen as ${h.seen_as}` : "", h.heard_as ? `heard as ${h.heard_as}` : ""].filter(Boolean);
  return `${h.object_id}: ${h.best_category}${confidence} (${hypothesisState(h)})${senses.length ? "; " + senses.join(", ") : ""}`;
}

// The whole list of a tick: the keyframe's, each changed one replacing the
// one of its object_id, new ones appended in the order listed.
export class HypothesisList {
  constructor() {
    this.keyframe = [];
    this.keyframeTick = -1;
    this.current = [];
  }

  setKeyframe(message) {
    this.keyframe = message.hypotheses || [];
    this.keyframeTick = message.tick;
    this.current = this.keyframe;
  }

  // Returns false when the changes belong to a keyframe not (yet) held.
  applyChanges(message) {
    if (message.keyframe_tick !== this.keyframeTick) return false;
    const changed = new Map((message.changed || []).map((h) => [h.object_id, h]));
    const list = this.keyframe.map((h) => changed.get(h.object_id) || h);
    const known = new Set(this.keyframe.map((h) => h.object_id));
    for (const h of message.changed || []) if (!known.has(h.object_id)) list.push(h);
    this.current = list;
    return true;
  }
}

export class HypothesisLayer {
  constructor(view) {
    this.view = view;
    this.group = new THREE.Group();
    view.add(this.group);
    const geometry = new THREE.OctahedronGeometry(0.28);
    this.markers = new InstancedSet(this.group, geometry, new THREE.MeshBasicMaterial({ color: 0xffffff }));
    this.hypotheses = [];
  }

  update(hypotheses) {
    this.hypotheses = hypotheses;
    this.markers.update(hypotheses.length, (i, placed) => {
      const h = hypotheses[i];
      placed.position.set(h.x, h.y, Math.max(h.z || 0, 0) + 2.3);
      placed.scale.setScalar(this.view.markerScale);
      return colourOf.get(hypothesisState(h));
    });
  }

  pickables() {
    return [this.markers.mesh];
  }

  hypothesisOfHit(hit) {
    if (!hit || hit.object !== this.markers.mesh || hit.instanceId === undefined) return null;
    return this.hypotheses[hit.instanceId] || null;
  }
}
