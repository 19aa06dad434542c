// The 3-D viewport: renderer, z-up camera with orbit controls (orbit, pan, zoom, reset),
// lights and the ground at z = 0.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export function createViewport(container) {
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  container.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xdfe6ee);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, renderer.domElement);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.0));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  sun.position.set(2, -3, 5);
  scene.add(sun);
  const ground = new THREE.Mesh(new THREE.PlaneGeometry(20, 20),
    new THREE.MeshStandardMaterial({ color: 0xb8c0b0, roughness: 1 }));
  ground.position.z = -0.001;
  scene.add(ground);
  const grid = new THREE.GridHelper(20, 80, 0x889080, 0x9aa394);
  grid.rotation.x = Math.PI / 2;
  scene.add(grid);

  const home = { position: new THREE.Vector3(2.4, -2.4, 1.6), target: new THREE.Vector3(0, 0, 0.8) };
  function reset() {
    camera.position.copy(home.position);
    controls.target.copy(home.target);
    controls.update();
  }
  // Aims the camera at a box (the robot) from the front-right.
  function frame(box) {
    if (box.isEmpty()) return;
    const center = box.getCenter(new THREE.Vector3());
    const size = box.getSize(new THREE.Vector3()).length();
    home.target.copy(center);
    home.position.copy(center).add(new THREE.Vector3(1.3, -1.3, 0.6).multiplyScalar(size));
    reset();
  }
  function resize() {
    const { clientWidth: w, clientHeight: h } = container;
    renderer.setSize(w, h);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
  }
  new ResizeObserver(resize).observe(container);
  resize();
  reset();
  const hooks = [];
  renderer.setAnimationLoop((t) => {
    hooks.forEach((f) => f(t));
    controls.update();
    renderer.render(scene, camera);
  });
  return { renderer, scene, camera, controls, reset, frame, onFrame: (f) => hooks.push(f), ground };
}
