// The SSV collision model drawn translucent, one colour per segment, each segment in its
// body frame (a child of the robot body it sits on); and the closest-pair lines.
import * as THREE from 'three';

const up = new THREE.Vector3(0, 1, 0);

function colour(i) {
  return new THREE.Color().setHSL((i * 0.618034) % 1, 0.65, 0.5);
}

// A capsule from a to b (three's capsule runs along y, centred).
function capsule(a, b, r, mat) {
  const d = new THREE.Vector3().subVectors(b, a);
  const mesh = new THREE.Mesh(new THREE.CapsuleGeometry(r, d.length(), 6, 16), mat);
  mesh.position.copy(a).addScaledVector(d, 0.5);
  if (d.lengthSq() > 0) mesh.quaternion.setFromUnitVectors(up, d.clone().normalize());
  return mesh;
}

// A triangle-swept sphere: spheres at the vertices, capsules on the edges, two faces offset
// by the radius along the normal.
function triangle(p, r, mat, group) {
  p.forEach((v, i) => group.add(capsule(v, p[(i + 1) % 3], r, mat)));
  const n = new THREE.Vector3().subVectors(p[1], p[0]).cross(new THREE.Vector3().subVectors(p[2], p[0]));
  if (n.lengthSq() === 0) return;
  n.normalize().multiplyScalar(r);
  const pos = [];
  for (const s of [1, -1]) for (const v of p) pos.push(v.x + s * n.x, v.y + s * n.y, v.z + s * n.z);
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
  g.computeVertexNormals();
  group.add(new THREE.Mesh(g, mat));
}

export function ssvObject(ssv, mat) {
  const p = ssv.points.map((v) => new THREE.Vector3(...v));
  const r = Math.max(ssv.radius, 1e-4);
  const group = new THREE.Group();
  if (ssv.kind === 'point') {
    const m = new THREE.Mesh(new THREE.SphereGeometry(r, 20, 14), mat);
    m.position.copy(p[0]);
    group.add(m);
  } else if (ssv.kind === 'line') group.add(capsule(p[0], p[1], r, mat));
  else triangle(p, r, mat, group);
  return group;
}

function dispose(object) {
  object.traverse((o) => { if (o.geometry) o.geometry.dispose(); });
  object.removeFromParent();
}

export function createSsvLayer(scene, robot) {
  let frames = [];
  let segments = [];
  let visible = true;
  const lines = new THREE.LineSegments(new THREE.BufferGeometry(),
    new THREE.LineBasicMaterial({ vertexColors: true, depthTest: false }));
  lines.renderOrder = 10;
  scene.add(lines);
  const layer = {
    segments: () => segments,
    frames: () => frames,
    // Rebuilds the drawing from a model of the API; `selected` is highlighted.
    show(model, selected) {
      frames.forEach(dispose);
      frames = model.bodies.map((b) => {
        const g = new THREE.Group();
        g.position.set(...b.offset.position);
        g.quaternion.set(...b.offset.quaternion);
        (b.body === null ? scene : robot.bodies[b.body]).add(g);
        return g;
      });
      segments = model.segments.map((s, i) => {
        const on = s.name === selected;
        const mat = new THREE.MeshStandardMaterial({ color: colour(i), transparent: true,
          opacity: on ? 0.6 : 0.28, depthWrite: false, emissive: on ? 0x442200 : 0x000000 });
        const g = new THREE.Group();
        g.name = s.name;
        s.ssvs.forEach((v) => g.add(ssvObject(v, mat)));
        frames[s.body].add(g);
        return g;
      });
      layer.setVisible(visible);
    },
    setVisible(on) {
      visible = on;
      segments.forEach((s) => { s.visible = on; });
    },
    // Lines between the closest points, red when touching, orange to yellow within d_a,
    // green beyond.
    showPairs(pairs, dA) {
      const pos = [];
      const col = [];
      for (const p of pairs) {
        if (p.distance === null) continue;
        const c = p.distance <= 0 ? new THREE.Color(0xff0000)
          : p.distance < dA ? new THREE.Color().setHSL(0.02 + 0.13 * (p.distance / dA), 1, 0.5)
            : new THREE.Color(0x22aa44);
        pos.push(...p.point_a, ...p.point_b);
        col.push(c.r, c.g, c.b, c.r, c.g, c.b);
      }
      lines.geometry.dispose();
      lines.geometry = new THREE.BufferGeometry();
      lines.geometry.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
      lines.geometry.setAttribute('color', new THREE.Float32BufferAttribute(col, 3));
    },
  };
  return layer;
}
