// Where the robot heard each sounding object (AUDIO: the acoustic estimate
// p_hat) against where it is (GT_OBJECTS): a ring at the heard position and
// a line from it to the true one. The ring is orange where the bearings
// crossed (located), grey where the estimate is only a point along a bearing.
import * as THREE from "three";
import { InstancedSet } from "./instanced_set.js";

const HEIGHT = 0.08;

export class AudioLayer {
  constructor(view) {
    this.view = view;
    this.group = new THREE.Group();
    view.add(this.group);
    const ring = new THREE.TorusGeometry(0.35, 0.06, 8, 24);
    this.rings = new InstancedSet(this.group, ring, new THREE.MeshBasicMaterial({ color: 0xffffff }));
    this.lines = new THREE.LineSegments(
      new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial({ color: 0xffa020, transparent: true, opacity: 0.8 }),
    );
    this.group.add(this.lines);
    this.percepts = [];
  }

  // percepts: AUDIO's; truthOf(id) -> the scene object or undefined.
  update(percepts, truthOf) {
    this.percepts = percepts;
    this.rings.update(percepts.length, (i, placed) => {
      placed.position.set(percepts[i].est_x, percepts[i].est_y, HEIGHT);
      placed.scale.setScalar(this.view.markerScale);
      return percepts[i].located === false ? 0x9a9a9a : 0xffa020;
    });
    const ends = [];
    for (const p of percepts) {
      const truth = truthOf(p.object_id);
      if (!truth) continue;
      ends.push(new THREE.Vector3(p.est_x, p.est_y, HEIGHT), new THREE.Vector3(truth.x, truth.y, HEIGHT));
    }
    this.lines.geometry.dispose();
    this.lines.geometry = new THREE.BufferGeometry().setFromPoints(ends);
  }

  pickables() {
    return [this.rings.mesh];
  }

  perceptOfHit(hit) {
    if (!hit || hit.object !== this.rings.mesh || hit.instanceId === undefined) return null;
    return this.percepts[hit.instanceId] || null;
  }
}
