// view3d.js — the 3D view of surface and volume canvases (three.js): samples as instanced
// spheres of their weight, coloured by type, a short tick along each sample's direction, the
// domain (a wire box, or the canvas mesh seen through), the strokes, and a drawing plane
// through the volume. Strokes are drawn by picking points on the domain's surface (mesh and
// shell canvases) or on the drawing plane. Left button: the current tool; right button:
// orbit; middle button: pan; wheel: zoom (OrbitControls).
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { api } from './api.js';
import { rgb } from './colors.js';
import { canvasMeshFile } from './canvas_presets.js';
import { strokeStyle } from './stroke_style.js';

export function createView3D(container, store) {
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0x121417);
  container.append(renderer.domElement);
  const canvas = renderer.domElement;
  canvas.tabIndex = 0;

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 5000);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, canvas);
  controls.mouseButtons = { LEFT: null, MIDDLE: THREE.MOUSE.PAN, RIGHT: THREE.MOUSE.ROTATE };
  controls.enableDamping = false;
  controls.addEventListener('change', () => request());

  scene.add(new THREE.HemisphereLight(0xdde6f0, 0x30281e, 1.1));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(0.6, -0.4, 1);
  scene.add(sun);

  const groups = {
    domain: new THREE.Group(),
    elements: new THREE.Group(),
    field: new THREE.Group(),
    strokes: new THREE.Group(),
    live: new THREE.Group(),
    plane: new THREE.Group(),
  };
  for (const g of Object.values(groups)) scene.add(g);

  let bounds = { min: [0, 0, 0], max: [20, 20, 12] };
  let meshPick = null; // the canvas mesh, for picking on its surface
  let meshFor = null; // the canvas text the mesh was loaded for
  let loadedCanvas = null; // the canvas text whose domain is shown and fitted
  let planeMesh = null;
  let frame = 0;
  const handlers = { start: null, move: null, end: null };
  const sphere = new THREE.SphereGeometry(1, 14, 10);

  function request() {
    if (frame || container.hidden) return;
    frame = requestAnimationFrame(() => {
      frame = 0;
      renderer.render(scene, camera);
      store.state.lastDrawAt = performance.now();
      if (store.state.view) store.state.drawnVersion = store.state.view.fetchedAt;
    });
  }

  function resize() {
    const w = container.clientWidth;
    const h = container.clientHeight;
    if (!w || !h) return;
    renderer.setSize(w, h, false);
    canvas.style.width = '100%';
    canvas.style.height = '100%';
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    request();
  }

  function clear(group) {
    for (const child of [...group.children]) {
      group.remove(child);
      child.traverse((o) => {
        if (o.geometry && o.geometry !== sphere) o.geometry.dispose();
        if (o.material) o.material.dispose();
      });
    }
  }

  function fit() {
    const c = bounds.min.map((v, a) => (v + bounds.max[a]) / 2);
    const r = Math.max(...bounds.max.map((v, a) => v - bounds.min[a])) || 1;
    controls.target.set(c[0], c[1], c[2]);
    camera.position.set(c[0] + r * 1.1, c[1] - r * 1.9, c[2] + r * 1.4);
    camera.near = r / 500;
    camera.far = r * 50;
    camera.updateProjectionMatrix();
    controls.update();
    request();
  }

  async function loadDomain(v) {
    const file = canvasMeshFile(v.canvas);
    if (meshFor === v.canvas) return;
    meshFor = v.canvas;
    clear(groups.domain);
    meshPick = null;
    const d = v.model.domain || {};
    if (file && /\.obj$/i.test(file)) {
      try {
        const geometry = parseObj(await api.fileText(file));
        geometry.computeBoundingBox();
        const bb = geometry.boundingBox;
        bounds = { min: bb.min.toArray(), max: bb.max.toArray() };
        const skin = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({
          color: 0x8fa3b8, transparent: true, opacity: 0.14, side: THREE.DoubleSide, depthWrite: false, roughness: 0.9,
        }));
        const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 25), new THREE.LineBasicMaterial({ color: 0x4a5562, transparent: true, opacity: 0.6 }));
        groups.domain.add(skin, edges);
        meshPick = skin;
      } catch (e) {
        store.set({ message: { text: `${file}: ${e.message}`, kind: 'error' } });
      }
    } else if (d.min && d.max) {
      bounds = { min: [...d.min], max: [...d.max] };
    } else {
      bounds = v.model.bounds;
    }
    const size = bounds.max.map((x, a) => x - bounds.min[a]);
    const box = new THREE.Box3Helper(new THREE.Box3(new THREE.Vector3(...bounds.min), new THREE.Vector3(...bounds.max)), 0x3d444d);
    groups.domain.add(box);
    const grid = new THREE.GridHelper(Math.max(size[0], size[1]) * 1.2, 24, 0x2c3238, 0x22272c);
    grid.rotation.x = Math.PI / 2;
    grid.position.set((bounds.min[0] + bounds.max[0]) / 2, (bounds.min[1] + bounds.max[1]) / 2, bounds.min[2]);
    groups.domain.add(grid);
    document.getElementById('pick-surface').parentElement.hidden = !meshPick;
    updatePlane();
    fit();
    loadedCanvas = v.canvas;
  }

  function planeZ() {
    return bounds.min[2] + store.state.planeHeight * (bounds.max[2] - bounds.min[2]);
  }

  function updatePlane() {
    clear(groups.plane);
    const size = bounds.max.map((x, a) => x - bounds.min[a]);
    const geometry = new THREE.PlaneGeometry(size[0], size[1]);
    planeMesh = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ color: 0xe0a040, transparent: true, opacity: 0.07, side: THREE.DoubleSide, depthWrite: false }));
    planeMesh.position.set((bounds.min[0] + bounds.max[0]) / 2, (bounds.min[1] + bounds.max[1]) / 2, planeZ());
    const rim = new THREE.LineSegments(new THREE.EdgesGeometry(geometry), new THREE.LineBasicMaterial({ color: 0xe0a040, transparent: true, opacity: 0.45 }));
    rim.position.copy(planeMesh.position);
    groups.plane.add(planeMesh, rim);
    request();
  }

  function updateElements(v) {
    clear(groups.elements);
    clear(groups.field);
    const model = v.model;
    let count = 0;
    for (const e of model.elements) count += e.samples.length;
    if (!count) return request();
    const mesh = new THREE.InstancedMesh(sphere, new THREE.MeshStandardMaterial({ roughness: 0.55, metalness: 0.05 }), count);
    const m = new THREE.Matrix4();
    const color = new THREE.Color();
    const ticks = [];
    let k = 0;
    for (const e of model.elements) {
      const t = model.types[e.type];
      const [r, g, b] = rgb(t.color);
      e.samples.forEach((p, s) => {
        const w = (t.weights[s] ?? t.weights[0] ?? 0.3) * e.scale;
        m.makeScale(w, w, w).setPosition(p[0], p[1], p[2]);
        mesh.setMatrixAt(k, m);
        mesh.setColorAt(k, color.setRGB(r, g, b, THREE.SRGBColorSpace));
        const d = v.directions[k];
        if (d) ticks.push(p[0], p[1], p[2], p[0] + d[0] * w * 1.8, p[1] + d[1] * w * 1.8, p[2] + d[2] * w * 1.8);
        ++k;
      });
    }
    mesh.instanceMatrix.needsUpdate = true;
    if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
    groups.elements.add(mesh);
    if (ticks.length) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.Float32BufferAttribute(ticks, 3));
      groups.field.add(new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: 0xc8d7eb, transparent: true, opacity: 0.35 })));
    }
    groups.field.visible = store.state.showField;
    request();
  }

  function strokeLine(op, opacity) {
    const pts = op.stroke.map((p) => new THREE.Vector3(p[0], p[1], p[2] ?? 0));
    if (pts.length === 1) pts.push(pts[0].clone().addScalar(1e-3));
    const style = strokeStyle(op, store.state);
    const [r, g, b] = rgb(style.color);
    const geometry = new THREE.BufferGeometry().setFromPoints(pts);
    return new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: new THREE.Color(r, g, b), transparent: true, opacity, depthTest: false }));
  }

  function updateStrokes() {
    clear(groups.strokes);
    if (store.state.showStrokes)
      for (const op of store.state.ops || []) if (op.stroke && op.stroke.length && op.stroke[0].length === 3) groups.strokes.add(strokeLine(op, 0.45));
    request();
  }

  // Picking: the canvas mesh's surface when asked and hit, else the drawing plane.
  const raycaster = new THREE.Raycaster();
  function pick(event) {
    const r = canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    if (meshPick && store.state.pickSurface) {
      const hit = raycaster.intersectObject(meshPick, false)[0];
      if (hit) return hit.point.toArray();
    }
    const hit = planeMesh ? raycaster.intersectObject(planeMesh, false)[0] : null;
    return hit ? hit.point.toArray() : null;
  }

  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('pointerdown', (event) => {
    if (event.button !== 0 || !handlers.start) return;
    const p = pick(event);
    if (!p) return;
    canvas.setPointerCapture(event.pointerId);
    handlers.start(p, event);
  });
  canvas.addEventListener('pointermove', (event) => {
    if (!(event.buttons & 1) || !handlers.move) return;
    const p = pick(event);
    if (p) handlers.move(p, event);
    store.set({ pointer: p });
  });
  canvas.addEventListener('pointerup', (event) => {
    if (event.button !== 0 || !handlers.end) return;
    const p = pick(event);
    handlers.end(p || null, event);
  });
  new ResizeObserver(resize).observe(container);

  store.on('view', (s) => {
    if (!s.view || s.view.dimension !== 3 || container.hidden) return;
    loadDomain(s.view).then(() => updateElements(s.view));
  });
  store.on(['ops', 'showStrokes', 'entries'], () => updateStrokes());
  store.on('showField', (s) => {
    groups.field.visible = s.showField;
    request();
  });
  store.on('planeHeight', () => updatePlane());

  return {
    element: container,
    handlers,
    fit,
    setLive(op) {
      clear(groups.live);
      if (op && op.stroke && op.stroke.length) groups.live.add(strokeLine(op, 0.95));
      request();
    },
    worldToClient(p) {
      const v = new THREE.Vector3(p[0], p[1], p[2] ?? 0).project(camera);
      const r = canvas.getBoundingClientRect();
      return [r.left + ((v.x + 1) / 2) * r.width, r.top + ((1 - v.y) / 2) * r.height];
    },
    show() {
      container.hidden = false;
      resize();
      const v = store.state.view;
      if (v && v.dimension === 3) loadDomain(v).then(() => updateElements(v));
      updateStrokes();
    },
    hide() {
      container.hidden = true;
    },
    // The canvas whose domain is shown (tests wait for it before drawing).
    get loadedCanvas() {
      return loadedCanvas;
    },
  };
}

// A Wavefront OBJ's triangles (v and f records; polygons fanned).
function parseObj(text) {
  const vertices = [];
  const index = [];
  for (const line of text.split('\n')) {
    const parts = line.trim().split(/\s+/);
    if (parts[0] === 'v') vertices.push(+parts[1], +parts[2], +parts[3]);
    else if (parts[0] === 'f') {
      const n = vertices.length / 3;
      const ids = parts.slice(1).map((s) => {
        const i = parseInt(s.split('/')[0], 10);
        return i < 0 ? n + i : i - 1;
      });
      for (let k = 1; k + 1 < ids.length; ++k) index.push(ids[0], ids[k], ids[k + 1]);
    }
  }
  if (!index.length) throw new Error('no faces in the mesh');
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(vertices, 3));
  geometry.setIndex(index);
  geometry.computeVertexNormals();
  return geometry;
}
