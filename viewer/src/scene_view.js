// The 3D view: renderer, z-up camera with orbit controls, lights, and rendering on demand (a
// frame is drawn only when something changed, so an idle page costs nothing).
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

export function createSceneView(container) {
  const renderer = new THREE.WebGLRenderer({ antialias: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  container.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xe9edf2);

  // World z is up, as in URDF and the task files.
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1);
  camera.position.set(2, -2, 1.5);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = false;

  const hemisphere = new THREE.HemisphereLight(0xffffff, 0x8a8f99, 1.6);
  hemisphere.position.set(0, 0, 1);
  scene.add(hemisphere);
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(1.5, -2.0, 3.0);
  scene.add(sun);
  const fill = new THREE.DirectionalLight(0xffffff, 0.5);
  fill.position.set(-2.0, 1.5, 1.0);
  scene.add(fill);

  let renderPending = false;
  const beforeRender = [];
  const view = {
    scene, camera, controls, renderer,
    renderCount: 0,
    requestRender() {
      if (renderPending) return;
      renderPending = true;
      requestAnimationFrame(draw);
    },
    /// fn(timeMs) runs before each frame; return true to ask for another frame.
    onBeforeRender(fn) { beforeRender.push(fn); },
  };
  function draw(time) {
    renderPending = false;
    let again = false;
    for (const fn of beforeRender) again = fn(time) || again;
    renderer.render(scene, camera);
    view.renderCount += 1;
    if (again) view.requestRender();
  }
  function resize() {
    const width = Math.max(1, container.clientWidth);
    const height = Math.max(1, container.clientHeight);
    renderer.setSize(width, height, false);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    view.requestRender();
  }
  controls.addEventListener('change', () => view.requestRender());
  new ResizeObserver(resize).observe(container);
  resize();
  return view;
}

/// Points the camera at `box` from `direction` (world frame), far enough to see all of it.
export function frameBox(view, box, direction) {
  const centre = box.getCenter(new THREE.Vector3());
  const radius = Math.max(0.05, box.getSize(new THREE.Vector3()).length() / 2);
  const fov = THREE.MathUtils.degToRad(view.camera.fov);
  // The bounding sphere's radius overstates a box's silhouette: come somewhat closer than it asks.
  const distance = 0.8 * radius / Math.sin(Math.min(fov, fov * view.camera.aspect) / 2);
  view.camera.position.copy(centre).addScaledVector(direction.clone().normalize(), distance);
  view.controls.target.copy(centre);
  view.controls.update();
  view.requestRender();
}
