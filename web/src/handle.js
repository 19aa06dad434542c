// The drag handle of the editor: a marker with three's TransformControls, at a vertex of
// the selected entry or, for the radius, one radius along the body's x axis from it.
import * as THREE from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';

// `moved(final)` follows a drag (final at its end).
export function createHandle(view, moved) {
  const marker = new THREE.Mesh(new THREE.SphereGeometry(0.012, 12, 8),
    new THREE.MeshBasicMaterial({ color: 0xff6600, depthTest: false }));
  marker.renderOrder = 12;
  view.scene.add(marker);
  const gizmo = new TransformControls(view.camera, view.renderer.domElement);
  gizmo.setSize(0.7);
  view.scene.add(gizmo.getHelper());
  gizmo.addEventListener('dragging-changed', (e) => {
    view.controls.enabled = !e.value;
    if (!e.value) moved(true);
  });
  gizmo.addEventListener('objectChange', () => moved(false));
  return {
    marker,
    hide() {
      gizmo.detach();
      marker.visible = false;
    },
    // At `point` (body frame of `frame`), plus `radius` along x in radius mode.
    place(frame, point, radius, radiusMode) {
      frame.updateMatrixWorld(true);
      const local = new THREE.Vector3(...point);
      if (radiusMode) local.x += radius;
      marker.position.copy(frame.localToWorld(local));
      marker.visible = true;
      gizmo.attach(marker);
      gizmo.showY = gizmo.showZ = !radiusMode;
    },
    // Where it is, in the body frame of `frame`.
    local: (frame) => frame.worldToLocal(marker.position.clone()),
  };
}
