// The robot's bodies: each a group placed at its world pose, holding its drawn geometry
// (boxes, cylinders, spheres, capsules, STL/OBJ/DAE meshes) at their poses in the body frame.
import * as THREE from 'three';
import { STLLoader } from 'three/addons/loaders/STLLoader.js';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { ColladaLoader } from 'three/addons/loaders/ColladaLoader.js';
import { VRMLLoader } from 'three/addons/loaders/VRMLLoader.js';

const material = new THREE.MeshStandardMaterial({ color: 0x9aa4b4, roughness: 0.6, metalness: 0.1 });

// A z-axis shape from three's y-axis geometry.
function alongZ(geometry) {
  geometry.rotateX(Math.PI / 2);
  return geometry;
}

function loadMesh(shape, holder) {
  const done = (object) => {
    object.scale.set(...shape.scale);
    holder.add(object);
  };
  const fail = (e) => console.warn(`mesh ${shape.url} not drawn: ${e}`);
  if (shape.format === 'stl') {
    new STLLoader().load(shape.url, (g) => done(new THREE.Mesh(g, material)), undefined, fail);
  } else if (shape.format === 'obj') {
    new OBJLoader().load(shape.url, (o) => {
      o.traverse((c) => { if (c.isMesh) c.material = material; });
      done(o);
    }, undefined, fail);
  } else if (shape.format === 'dae') {
    new ColladaLoader().load(shape.url, (c) => done(c.scene), undefined, fail);
  } else if (shape.format === 'wrl') {
    new VRMLLoader().load(shape.url, done, undefined, fail);
  }
}

function element(geometry) {
  const holder = new THREE.Group();
  const { position, quaternion } = geometry.pose;
  holder.position.set(...position);
  holder.quaternion.set(...quaternion);
  const s = geometry.shape;
  const mesh = (g) => holder.add(new THREE.Mesh(g, material));
  if (s.type === 'box') mesh(new THREE.BoxGeometry(...s.size));
  else if (s.type === 'sphere') mesh(new THREE.SphereGeometry(s.radius, 24, 16));
  else if (s.type === 'cylinder') mesh(alongZ(new THREE.CylinderGeometry(s.radius, s.radius, s.length, 24)));
  else if (s.type === 'capsule') mesh(alongZ(new THREE.CapsuleGeometry(s.radius, s.length, 8, 16)));
  else if (s.type === 'mesh') loadMesh(s, holder);
  return holder;
}

export function createRobot(scene, sceneJson) {
  const root = new THREE.Group();
  scene.add(root);
  const bodies = sceneJson.bodies.map((b) => {
    const group = new THREE.Group();
    group.name = b.name;
    b.geometry.forEach((g) => group.add(element(g)));
    root.add(group);
    return group;
  });
  sceneJson.world.forEach((g) => root.add(element(g)));
  return {
    root,
    bodies,
    // See-through bodies, so that the SSVs inside them show.
    setOpacity(opacity) {
      material.transparent = opacity < 1;
      material.opacity = opacity;
      material.depthWrite = opacity >= 1;
    },
    // Poses as [x, y, z, qx, qy, qz, qw] or {position, quaternion}, one per body.
    setPoses(poses) {
      poses.forEach((p, i) => {
        const b = bodies[i];
        if (Array.isArray(p)) {
          b.position.set(p[0], p[1], p[2]);
          b.quaternion.set(p[3], p[4], p[5], p[6]);
        } else {
          b.position.set(...p.position);
          b.quaternion.set(...p.quaternion);
        }
      });
      root.updateMatrixWorld(true);
    },
  };
}
