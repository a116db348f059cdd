// Many copies of one shape drawn in one call (THREE.InstancedMesh), with
// room that grows when more are needed, so that a district of hundreds of
// objects costs a handful of draw calls and a message rewrites matrices only.
import * as THREE from "three";

const scratch = new THREE.Object3D();
const colour = new THREE.Color();

export class InstancedSet {
  constructor(parent, geometry, material, capacity = 16) {
    this.parent = parent;
    this.geometry = geometry;
    this.material = material;
    this.mesh = null;
    this.build(capacity);
  }

  build(capacity) {
    if (this.mesh) {
      this.parent.remove(this.mesh);
      this.mesh.dispose();
    }
    this.mesh = new THREE.InstancedMesh(this.geometry, this.material, capacity);
    this.mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
    this.mesh.setColorAt(0, colour.set(0xffffff));
    this.mesh.count = 0;
    this.mesh.frustumCulled = false;  // instances spread over the world
    this.parent.add(this.mesh);
  }

  // Draws `count` instances; place(i, object3d) sets the i-th one's position,
  // rotation and scale on a scratch object and returns its colour (a number).
  update(count, place) {
    if (count > this.mesh.instanceMatrix.count) this.build(Math.max(count, 2 * this.mesh.instanceMatrix.count));
    for (let i = 0; i < count; i++) {
      scratch.position.set(0, 0, 0);
      scratch.rotation.set(0, 0, 0);
      scratch.scale.set(1, 1, 1);
      const rgb = place(i, scratch);
      scratch.updateMatrix();
      this.mesh.setMatrixAt(i, scratch.matrix);
      this.mesh.setColorAt(i, colour.set(rgb));
    }
    this.mesh.count = count;
    this.mesh.instanceMatrix.needsUpdate = true;
    if (this.mesh.instanceColor) this.mesh.instanceColor.needsUpdate = true;
    // Raycasting tests this sphere first; three.js keeps it from the first use.
    this.mesh.computeBoundingSphere();
    this.mesh.boundingBox = null;
  }

  set visible(on) {
    this.mesh.visible = on;
  }
}
