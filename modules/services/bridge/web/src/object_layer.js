// The scene's objects (GT_OBJECTS, lcmtypes/scene_object_t.lcm) as boxes and
// cylinders in their colours: one instanced mesh per shape.
import * as THREE from "three";
import { InstancedSet } from "./instanced_set.js";

const SHAPE_BOX = 1;
const SHAPE_CYLINDER = 2;
const DEG = Math.PI / 180;

function unitBox() {
  const geometry = new THREE.BoxGeometry(1, 1, 1);
  geometry.translate(0, 0, 0.5);  // base on the ground
  return geometry;
}

function unitCylinder() {
  const geometry = new THREE.CylinderGeometry(0.5, 0.5, 1, 20);
  geometry.rotateX(Math.PI / 2);  // axis along z
  geometry.translate(0, 0, 0.5);
  return geometry;
}

export class ObjectLayer {
  constructor(view) {
    this.group = new THREE.Group();
    view.add(this.group);
    const material = () => new THREE.MeshLambertMaterial({ color: 0xffffff });
    this.boxes = new InstancedSet(this.group, unitBox(), material());
    this.cylinders = new InstancedSet(this.group, unitCylinder(), material());
    this.objects = [];        // the last message's objects, scenario order
    this.byId = new Map();    // id -> object
    this.boxIds = [];         // instance index -> object id
    this.cylinderIds = [];
  }

  // Replaces what is drawn by the objects of one GT_OBJECTS message.
  update(objects) {
    this.objects = objects;
    this.byId = new Map(objects.map((object) => [object.id, object]));
    const boxes = objects.filter((o) => o.shape === SHAPE_BOX);
    const cylinders = objects.filter((o) => o.shape === SHAPE_CYLINDER);
    this.boxIds = boxes.map((o) => o.id);
    this.cylinderIds = cylinders.map((o) => o.id);
    this.boxes.update(boxes.length, (i, placed) => place(boxes[i], placed, boxes[i].size_x, boxes[i].size_y));
    this.cylinders.update(cylinders.length, (i, placed) => {
      const o = cylinders[i];
      const diameter = o.radius > 0 ? 2 * o.radius : Math.max(o.size_x, 0.1);
      return place(o, placed, diameter, diameter);
    });
  }

  get drawnCount() {
    return this.boxIds.length + this.cylinderIds.length;
  }

  pickables() {
    return [this.boxes.mesh, this.cylinders.mesh];
  }

  // The object of a raycast hit on one of pickables(), or null.
  objectOfHit(hit) {
    if (!hit || hit.instanceId === undefined) return null;
    const ids = hit.object === this.boxes.mesh ? this.boxIds : hit.object === this.cylinders.mesh ? this.cylinderIds : null;
    return ids ? this.byId.get(ids[hit.instanceId]) || null : null;
  }
}

function place(object, placed, sizeX, sizeY) {
  placed.position.set(object.x, object.y, object.z || 0);
  placed.rotation.set(0, 0, (object.yaw || 0) * DEG);
  placed.scale.set(Math.max(sizeX, 0.02), Math.max(sizeY, 0.02), Math.max(object.size_z, 0.02));
  return object.color_rgb & 0xffffff;
}
