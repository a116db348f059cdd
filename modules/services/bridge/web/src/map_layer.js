// The obstacle map M_O as a texture on the ground: OBSTACLE_MAP at keyframes
// (the whole map), OBSTACLE_MAP_CHANGES every tick (the rectangle changed
// since that keyframe, written over it). One byte per cell is uploaded and
// a small shader colours it: unknown clear, free pale, occupied dark.
import * as THREE from "three";
import { decodeCells } from "./bytes.js";

const fragmentShader = `
uniform sampler2D cells;
varying vec2 vUv;
void main() {
  float cell = floor(texture2D(cells, vUv).r * 255.0 + 0.5);
  if (cell < 0.5) discard;                                      // unknown
  if (cell < 1.5) gl_FragColor = vec4(0.80, 0.86, 0.78, 0.35);  // free
  else gl_FragColor = vec4(0.08, 0.08, 0.10, 0.85);             // occupied
}`;
const vertexShader = `
varying vec2 vUv;
void main() { vUv = uv; gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0); }`;

export class MapLayer {
  constructor(view) {
    this.mesh = null;
    this.view = view;
    this.keyframeTick = -1;
    this.cells = null;
    this.width = 0;
    this.height = 0;
  }

  keyframe(map) {
    const cells = decodeCells(map.data, map.encoding, map.width * map.height);
    if (!this.mesh || map.width !== this.width || map.height !== this.height) this.build(map, cells);
    else this.cells.set(cells);
    this.keyframeTick = map.tick;
    this.placeAt(map);
    this.texture.needsUpdate = true;
  }

  // Changes apply to their keyframe only; others wait for the next keyframe.
  changes(change) {
    if (!this.mesh || change.keyframe_tick !== this.keyframeTick || !(change.width > 0 && change.height > 0)) return;
    if (change.x0 + change.width > this.width || change.y0 + change.height > this.height) return;
    const rect = decodeCells(change.data, change.encoding, change.width * change.height);
    for (let row = 0; row < change.height; row++) {
      const from = row * change.width;
      this.cells.set(rect.subarray(from, from + change.width), (change.y0 + row) * this.width + change.x0);
    }
    this.texture.needsUpdate = true;
  }

  build(map, cells) {
    if (this.mesh) this.view.scene.remove(this.mesh);
    this.width = map.width;
    this.height = map.height;
    this.cells = new Uint8Array(cells);
    this.texture = new THREE.DataTexture(this.cells, map.width, map.height, THREE.RedFormat, THREE.UnsignedByteType);
    this.texture.magFilter = THREE.NearestFilter;
    this.texture.minFilter = THREE.NearestFilter;
    this.texture.unpackAlignment = 1;
    const material = new THREE.ShaderMaterial({
      uniforms: { cells: { value: this.texture } },
      vertexShader,
      fragmentShader,
      transparent: true,
      depthWrite: false,
    });
    this.mesh = new THREE.Mesh(new THREE.PlaneGeometry(1, 1), material);
    this.mesh.renderOrder = 1;
    this.view.add(this.mesh);
  }

  // Cell (0,0) at (origin_x, origin_y), rows along +y: texture row 0 at the plane's bottom edge.
  placeAt(map) {
    const sizeX = map.width * map.resolution;
    const sizeY = map.height * map.resolution;
    this.mesh.scale.set(sizeX, sizeY, 1);
    this.mesh.position.set(map.origin_x + sizeX / 2, map.origin_y + sizeY / 2, 0.015);
  }
}
