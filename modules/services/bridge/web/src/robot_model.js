// The robot (ROBOT_STATE, lcmtypes/robot_state_t.lcm): its platform, its
// head on a mast and an arrow along its gaze (platform yaw + head pan, head tilt).
import * as THREE from "three";

const DEG = Math.PI / 180;
const GAZE_LENGTH = 2.5;

export class RobotModel {
  constructor(view) {
    this.platform = new THREE.Group();
    this.platform.visible = false;  // until the first ROBOT_STATE
    view.add(this.platform);
    const body = new THREE.Mesh(
      new THREE.CylinderGeometry(1, 1, 1, 24).rotateX(Math.PI / 2).translate(0, 0, 0.5),
      new THREE.MeshLambertMaterial({ color: 0xe8e8e8 }),
    );
    this.body = body;
    this.platform.add(body);
    const nose = new THREE.Mesh(new THREE.BoxGeometry(0.25, 0.12, 0.05), new THREE.MeshLambertMaterial({ color: 0xff8c1a }));
    this.nose = nose;
    this.platform.add(nose);
    this.head = new THREE.Group();
    this.platform.add(this.head);
    const skull = new THREE.Mesh(new THREE.SphereGeometry(0.14, 16, 12), new THREE.MeshLambertMaterial({ color: 0xffd27f }));
    this.head.add(skull);
    this.tilt = new THREE.Group();
    this.head.add(this.tilt);
    this.gaze = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 0, 0), GAZE_LENGTH, 0xffd000, 0.35, 0.18);
    this.tilt.add(this.gaze);
    this.mast = new THREE.Mesh(new THREE.CylinderGeometry(0.03, 0.03, 1, 8).rotateX(Math.PI / 2).translate(0, 0, 0.5),
      new THREE.MeshLambertMaterial({ color: 0x888888 }));
    this.platform.add(this.mast);
  }

  update(state) {
    const radius = state.radius > 0 ? state.radius : 0.35;
    const headHeight = state.camera_height > 0 ? state.camera_height : 1.5;
    this.platform.visible = true;
    this.platform.position.set(state.x, state.y, 0);
    this.platform.rotation.set(0, 0, state.yaw * DEG);
    this.body.scale.set(radius, radius, 0.35);
    this.nose.position.set(radius, 0, 0.37);
    this.mast.scale.set(1, 1, headHeight);
    this.head.position.set(0, 0, headHeight);
    this.head.rotation.set(0, 0, (state.head_yaw || 0) * DEG);
    this.tilt.rotation.set(0, -(state.head_pitch || 0) * DEG, 0);  // up positive
    this.body.material.color.set(state.collided ? 0xff5050 : 0xe8e8e8);
  }
}
