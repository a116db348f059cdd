// The 3-D view: renderer, camera, orbit controls, the ground, and the layers
// drawn on it. World frame as in BEFT: x east, y north, z up, metres.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";

// The shortest time between two frames drawn for the run's changes [ms]:
// with a GPU, and when WebGL is drawn in software on the CPU (SwiftShader,
// llvmpipe: a frame of the full view costs tens of milliseconds of a core
// that the run beside the page needs).
const DATA_FRAME_MS = 100;
const SOFTWARE_DATA_FRAME_MS = 1000;

// Whether this browser draws WebGL in software, asked of a context of its own
// (the renderer's antialiasing is chosen before its context exists).
function webGlInSoftware() {
  const canvas = document.createElement("canvas");
  const gl = canvas.getContext("webgl2") || canvas.getContext("webgl");
  if (!gl) return false;
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  const lose = gl.getExtension("WEBGL_lose_context");
  if (lose) lose.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}

THREE.Object3D.DEFAULT_UP.set(0, 0, 1);

export class SceneView {
  constructor(container) {
    this.container = container;
    // In software: no multisampling and one pixel per CSS pixel (a quarter
    // of the work or less), and at most one frame a second for the run's
    // changes (what a person does is drawn at once).
    this.software = webGlInSoftware();
    this.dataFrameMs = this.software ? SOFTWARE_DATA_FRAME_MS : DATA_FRAME_MS;
    this.renderer = new THREE.WebGLRenderer({ antialias: !this.software, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(this.software ? 1 : Math.min(window.devicePixelRatio || 1, 2));
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0x1b1f24);
    this.camera = new THREE.PerspectiveCamera(50, 1, 0.1, 2000);
    this.camera.position.set(-10, -15, 25);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.target.set(15, 10, 0);
    this.controls.update();
    // Drawn on the next animation frame after a change only: a held run or
    // a still view costs no CPU (software WebGL draws a frame in ~100 ms).
    this.needsRender = true;
    this.dataChanged = false;
    this.lastRenderMs = -Infinity;
    this.onInteraction = null;  // set by the page: a person turned or resized the view
    this.controls.addEventListener("change", () => this.invalidate());
    this.addLights();
    this.ground = this.makeGround();
    this.worldSize = null;
    // Markers (hypotheses, heard positions, waypoints) grow with the world so
    // that a 160 m district's stay visible from where the camera starts.
    this.markerScale = 1;
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  addLights() {
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x404040, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.4);
    sun.position.set(-30, -20, 60);
    this.scene.add(sun);
  }

  // A 1 x 1 plane scaled to the world when its size is known (GT_OBJECTS).
  makeGround() {
    const ground = new THREE.Mesh(
      new THREE.PlaneGeometry(1, 1),
      new THREE.MeshLambertMaterial({ color: 0x5b5e55 }),
    );
    ground.scale.set(30, 20, 1);
    ground.position.set(15, 10, 0);
    this.scene.add(ground);
    const border = new THREE.LineSegments(
      new THREE.EdgesGeometry(new THREE.PlaneGeometry(1, 1)),
      new THREE.LineBasicMaterial({ color: 0xc8c8c8 }),
    );
    ground.add(border);
    return ground;
  }

  // Sets the ground to the world's extent and, the first time, aims the camera at it.
  setWorldSize(width, height) {
    if (!(width > 0 && height > 0)) return;
    const changed = !this.worldSize || this.worldSize.width !== width || this.worldSize.height !== height;
    if (!changed) return;
    this.ground.scale.set(width, height, 1);
    this.ground.position.set(width / 2, height / 2, 0);
    const span = Math.max(width, height);
    this.controls.target.set(width / 2, height / 2, 0);
    this.camera.position.set(width / 2 - 0.1 * span, -0.45 * span, 0.75 * span);
    this.camera.far = Math.max(2000, span * 10);
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.worldSize = { width, height };
    this.markerScale = Math.max(1, span / 40);
  }

  add(object) {
    this.scene.add(object);
  }

  resize() {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    // A new size reallocates the drawing buffer: only when it changed.
    if (width === this.width && height === this.height) return;
    this.width = width;
    this.height = height;
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.invalidate();
  }

  // What a person does (orbit, zoom, resize) is drawn on the next frame;
  // what the run changes (fromData) at most every dataFrameMs: a run at
  // full speed changes the scene a hundred times a second, and drawing each
  // would take a core from the run beside it.
  invalidate(fromData = false) {
    if (fromData) {
      this.dataChanged = true;
    } else {
      this.needsRender = true;
      if (this.onInteraction) this.onInteraction();
    }
  }

  render(nowMs) {
    this.controls.update();
    if (this.dataChanged && nowMs - this.lastRenderMs >= this.dataFrameMs) {
      this.needsRender = true;
      this.dataChanged = false;
    }
    if (!this.needsRender) return false;
    this.needsRender = false;
    this.lastRenderMs = nowMs;
    this.renderer.render(this.scene, this.camera);
    return true;
  }

  // Normalised device coordinates of a pointer event over the canvas.
  pointerNdc(event) {
    const rect = this.renderer.domElement.getBoundingClientRect();
    return new THREE.Vector2(
      ((event.clientX - rect.left) / rect.width) * 2 - 1,
      -((event.clientY - rect.top) / rect.height) * 2 + 1,
    );
  }

  // The world point under the pointer on the ground plane z = 0, or null.
  groundPoint(ndc) {
    const raycaster = new THREE.Raycaster();
    raycaster.setFromCamera(ndc, this.camera);
    const hit = new THREE.Vector3();
    const plane = new THREE.Plane(new THREE.Vector3(0, 0, 1), 0);
    return raycaster.ray.intersectPlane(plane, hit) ? hit : null;
  }

  // Where a world point appears, in the page's client pixels (for tests and tools).
  screenOf(x, y, z = 0) {
    const ndc = new THREE.Vector3(x, y, z).project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((ndc.x + 1) / 2) * rect.width, y: rect.top + ((1 - ndc.y) / 2) * rect.height };
  }

  // The nearest hit among `objects` (meshes, instanced meshes), or null.
  pick(ndc, objects) {
    const raycaster = new THREE.Raycaster();
    raycaster.setFromCamera(ndc, this.camera);
    const hits = raycaster.intersectObjects(objects, false);
    return hits.length ? hits[0] : null;
  }
}
