// The planned path (PLAN_RESULT): white dots at the waypoints and, as in the
// paper's Fig. 3, red-white arrows giving the platform's intended heading there.
import * as THREE from "three";
import { mergeGeometries } from "three/addons/utils/BufferGeometryUtils.js";
import { InstancedSet } from "./instanced_set.js";

const DEG = Math.PI / 180;
const HEIGHT = 0.06;

function coloured(geometry, rgb) {
  const colour = new THREE.Color(rgb);
  const colours = new Float32Array(geometry.attributes.position.count * 3);
  for (let i = 0; i < colours.length; i += 3) colours.set([colour.r, colour.g, colour.b], i);
  geometry.setAttribute("color", new THREE.BufferAttribute(colours, 3));
  return geometry;
}

// An arrow along +x from the origin, 0.6 m long: a white shaft, a red head.
function arrowGeometry() {
  const shaft = coloured(new THREE.BoxGeometry(0.4, 0.05, 0.02).translate(0.2, 0, 0).toNonIndexed(), 0xffffff);
  const head = new THREE.ConeGeometry(0.09, 0.2, 12).rotateZ(-Math.PI / 2).translate(0.5, 0, 0).toNonIndexed();
  head.deleteAttribute("uv");
  shaft.deleteAttribute("uv");
  return mergeGeometries([shaft, coloured(head, 0xe02020)]);
}

export class PathLayer {
  constructor(view) {
    this.view = view;
    this.group = new THREE.Group();
    view.add(this.group);
    this.dots = new InstancedSet(this.group, new THREE.SphereGeometry(0.1, 10, 8), new THREE.MeshBasicMaterial({ color: 0xffffff }));
    this.arrows = new InstancedSet(this.group, arrowGeometry(), new THREE.MeshBasicMaterial({ vertexColors: true }));
    this.line = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xffffff, transparent: true, opacity: 0.5 }));
    this.group.add(this.line);
    this.waypointCount = 0;
  }

  update(result) {
    const points = result.success === false ? [] : result.waypoints || [];
    this.waypointCount = points.length;
    this.dots.update(points.length, (i, placed) => {
      placed.position.set(points[i].x, points[i].y, HEIGHT);
      placed.scale.setScalar(this.view.markerScale);
      return 0xffffff;
    });
    this.arrows.update(points.length, (i, placed) => {
      placed.position.set(points[i].x, points[i].y, HEIGHT + 0.02);
      placed.rotation.set(0, 0, (points[i].yaw || 0) * DEG);
      placed.scale.setScalar(this.view.markerScale);
      return 0xffffff;  // the vertex colours give red and white
    });
    const line = points.map((p) => new THREE.Vector3(p.x, p.y, HEIGHT));
    this.line.geometry.dispose();
    this.line.geometry = new THREE.BufferGeometry().setFromPoints(line);
  }
}
