// The script of a `resharp view` page: reads the meshes the page carries (base64 of typed
// arrays, described by the JSON block #resharp-meta), draws the input and the restored mesh side
// by side under one camera, and wires the toggles. esbuild bundles it with three.js into one
// script that the CLI inlines, so the page opens with no network.
//
// The page reports how it went in <html data-status>: "rendered" once the first frame is shown,
// or "error: ..." (tests and the benchmark wait for it).

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const root = document.documentElement;
const setStatus = (text) => { root.dataset.status = text; };
window.addEventListener('error', (event) => setStatus(`error: ${event.message}`));
window.addEventListener('unhandledrejection', (event) => setStatus(`error: ${event.reason}`));

const kSurface = [0.72, 0.74, 0.78];
const kSharpEdge = [16, 96, 255];

/// The bytes of the base64 block with this id as an array of `Type`.
function decode(id, Type) {
    const text = document.getElementById(id).textContent.trim();
    let bytes;
    if (Uint8Array.fromBase64) {
        bytes = Uint8Array.fromBase64(text);
    } else {
        const chars = atob(text);
        bytes = new Uint8Array(chars.length);
        for (let i = 0; i < chars.length; ++i) bytes[i] = chars.charCodeAt(i);
    }
    return new Type(bytes.buffer, bytes.byteOffset, bytes.byteLength / Type.BYTES_PER_ELEMENT);
}

/// Positions of the restored mesh: the first `shared` are the input's (the page stores them once).
function restoredPositions(meta, inputPositions) {
    const extra = decode('restored-positions', Float32Array);
    const shared = meta.restored.shared_vertices * 3;
    const all = new Float32Array(shared + extra.length);
    all.set(inputPositions.subarray(0, shared));
    all.set(extra, shared);
    return all;
}

/// The mesh as three.js draws it fastest: one vertex per mesh vertex, faces by index.
function indexedGeometry(positionAttribute, triangles) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', positionAttribute);
    geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
    geometry.computeBoundingSphere();
    return geometry;
}

/// Lines along the three edges of every triangle, on the indexed positions (built on first use).
function wireframeGeometry(positionAttribute, triangles) {
    const index = new Uint32Array(triangles.length * 2);
    for (let f = 0; f < triangles.length; f += 3) {
        const [a, b, c] = [triangles[f], triangles[f + 1], triangles[f + 2]];
        index.set([a, b, b, c, c, a], f * 2);
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', positionAttribute);
    geometry.setIndex(new THREE.BufferAttribute(index, 1));
    return geometry;
}

/// Colour bytes are sRGB (as in PLY files and CSS); three.js takes vertex colours as linear.
const kSrgbToLinear = Uint8Array.from({ length: 256 },
    (_, i) => Math.round(255 * new THREE.Color().setRGB(i / 255, 0, 0, THREE.SRGBColorSpace).r));

/// The faces that `colorOf(f)` colours (it gives an sRGB byte triple or null), one vertex per
/// corner so that each face has its own colour: drawn over the plain mesh.
function coloredFaces(positions, triangles, colorOf) {
    const faces = [];
    for (let f = 0; f < triangles.length / 3; ++f) {
        if (colorOf(f)) faces.push(f);
    }
    const corners = new Float32Array(faces.length * 9);
    const colors = new Uint8Array(faces.length * 9);
    faces.forEach((f, i) => {
        const rgb = colorOf(f);
        for (let k = 0; k < 3; ++k) {
            const v = triangles[3 * f + k] * 3;
            for (let c = 0; c < 3; ++c) {
                corners[9 * i + 3 * k + c] = positions[v + c];
                colors[9 * i + 3 * k + c] = kSrgbToLinear[rgb[c]];
            }
        }
    });
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(corners, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3, true));
    return geometry;
}

/// Flat-shaded, lit by a light that follows the camera. The plain meshes are pushed back in
/// depth a little so that overlays on the same triangles and lines on their edges win.
function surfaceMaterial(options) {
    return new THREE.MeshStandardMaterial({
        flatShading: true, metalness: 0.15, roughness: 0.55, side: THREE.DoubleSide, ...options,
    });
}

/// An 8-bit RGB triple as a three.js colour (sRGB, as CSS).
function rgbColor(rgb) {
    return new THREE.Color().setRGB(rgb[0] / 255, rgb[1] / 255, rgb[2] / 255, THREE.SRGBColorSpace);
}

function pointsAt(positions, selected, rgb) {
    const chosen = [];
    for (let v = 0; v < selected.length; ++v) {
        if (selected[v]) chosen.push(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(chosen, 3));
    return new THREE.Points(geometry,
        new THREE.PointsMaterial({ color: rgbColor(rgb), size: 4, sizeAttenuation: false }));
}

/// A scene with one plain mesh, its light following the camera, and room for overlays.
function makeView(geometry) {
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xffffff);
    scene.add(new THREE.HemisphereLight(0xffffff, 0x606070, 1.2));
    const light = new THREE.DirectionalLight(0xffffff, 2.0);
    scene.add(light, light.target);
    const color = new THREE.Color(...kSurface);
    scene.add(new THREE.Mesh(geometry, surfaceMaterial({
        color, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    })));
    return { scene, light };
}

function buildTable(report) {
    const table = document.getElementById('numbers');
    const addRow = (label, value, isHeading) => {
        const row = table.insertRow();
        const cell = row.insertCell();
        cell.textContent = label;
        if (isHeading) { cell.colSpan = 2; cell.className = 'section'; return; }
        row.insertCell().textContent = value;
    };
    const walk = (object, depth) => {
        for (const [key, value] of Object.entries(object)) {
            const label = key.replaceAll('_', ' ');
            if (value !== null && typeof value === 'object') {
                addRow(label, '', true);
                walk(value, depth + 1);
            } else {
                addRow(label, typeof value === 'number' && !Number.isInteger(value)
                    ? value.toPrecision(3) : String(value));
            }
        }
    };
    walk(report, 0);
}

/// Camera from the URL (#camera=px,py,pz,tx,ty,tz), so a view can be shared and shot again.
function cameraFromHash() {
    const match = /camera=([-0-9.e,]+)/.exec(location.hash);
    if (!match) return null;
    const values = match[1].split(',').map(Number);
    return values.length === 6 && values.every(Number.isFinite) ? values : null;
}

function main() {
    const parsedMs = performance.now();  // the whole HTML is parsed: this script comes last
    const meta = JSON.parse(document.getElementById('resharp-meta').textContent);
    const inputPositions = decode('input-positions', Float32Array);
    const inputTriangles = decode('input-triangles', Uint32Array);
    const outPositions = restoredPositions(meta, inputPositions);
    const outTriangles = decode('restored-triangles', Uint32Array);
    const sharp = decode('sharp-edges', Uint32Array);
    const segments = meta.segments ? {
        edgeVertex: decode('segment-edge-vertices', Uint8Array),
        role: decode('segment-roles', Uint8Array),
        patch: decode('segment-patches', Uint8Array),
    } : null;

    const decodedMs = performance.now();
    const inAttribute = new THREE.BufferAttribute(inputPositions, 3);
    const outAttribute = new THREE.BufferAttribute(outPositions, 3);
    const inputGeometry = indexedGeometry(inAttribute, inputTriangles);
    const left = makeView(inputGeometry);
    const right = makeView(indexedGeometry(outAttribute, outTriangles));

    const sharpGeometry = new THREE.BufferGeometry();
    sharpGeometry.setAttribute('position', outAttribute);
    sharpGeometry.setIndex(new THREE.BufferAttribute(sharp, 1));
    const sharpLines = new THREE.LineSegments(sharpGeometry,
        new THREE.LineBasicMaterial({ color: rgbColor(kSharpEdge) }));
    right.scene.add(sharpLines);

    // The segmentation's colours over the plain input: the edge and corner triangles, and with
    // the patches on every face. Rebuilt when a toggle changes.
    const overlay = new THREE.Mesh(new THREE.BufferGeometry(), surfaceMaterial({ vertexColors: true }));
    left.scene.add(overlay);
    const paintInput = (show) => {
        const colorOf = (f) => {
            const role = segments.role[f];
            if (show.bands && role === 1) return meta.colors.edge_triangle;
            if (show.bands && role === 2) return meta.colors.corner_triangle;
            return show.patches ? segments.patch.subarray(3 * f, 3 * f + 3) : null;
        };
        overlay.geometry.dispose();
        overlay.geometry = coloredFaces(inputPositions, inputTriangles, colorOf);
    };

    const edgePoints = segments
        ? pointsAt(inputPositions, segments.edgeVertex, meta.colors.edge_vertex) : null;
    if (edgePoints) left.scene.add(edgePoints);

    const wireMaterial = new THREE.LineBasicMaterial({ color: 0x303030, transparent: true, opacity: 0.35 });
    let wires = null;
    const showWires = (visible) => {
        if (visible && !wires) {
            wires = [
                new THREE.LineSegments(wireframeGeometry(inAttribute, inputTriangles), wireMaterial),
                new THREE.LineSegments(wireframeGeometry(outAttribute, outTriangles), wireMaterial),
            ];
            left.scene.add(wires[0]);
            right.scene.add(wires[1]);
        }
        if (wires) wires.forEach((w) => { w.visible = visible; });
    };

    const canvas = document.getElementById('canvas');
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio);
    const sphere = inputGeometry.boundingSphere;
    const camera = new THREE.PerspectiveCamera(35, 1, sphere.radius / 100, sphere.radius * 100);
    const controls = new OrbitControls(camera, canvas);
    const fromHash = cameraFromHash();
    if (fromHash) {
        camera.position.set(fromHash[0], fromHash[1], fromHash[2]);
        controls.target.set(fromHash[3], fromHash[4], fromHash[5]);
    } else {
        // Far enough for the bounding sphere to fit the narrower of the two angles of view.
        const aspect = canvas.clientWidth / 2 / Math.max(1, canvas.clientHeight);
        const vertical = THREE.MathUtils.degToRad(camera.fov) / 2;
        const half = Math.min(vertical, Math.atan(Math.tan(vertical) * aspect));
        controls.target.copy(sphere.center);
        camera.position.copy(sphere.center)
            .add(new THREE.Vector3(1, -1.4, 1.1).setLength(1.05 * sphere.radius / Math.sin(half)));
    }
    camera.up.set(0, 0, 1);
    controls.update();

    const render = () => {
        const width = canvas.clientWidth, height = canvas.clientHeight;
        renderer.setSize(width, height, false);
        camera.aspect = width / 2 / height;
        camera.updateProjectionMatrix();
        renderer.setScissorTest(true);
        [left, right].forEach((view, i) => {
            view.light.position.copy(camera.position);
            view.light.target.position.copy(controls.target);
            const x = Math.round(i * width / 2);
            renderer.setViewport(x, 0, Math.round(width / 2), height);
            renderer.setScissor(x, 0, Math.round(width / 2), height);
            renderer.render(view.scene, camera);
        });
    };
    controls.addEventListener('change', render);
    controls.addEventListener('end', () => {
        const p = camera.position, t = controls.target;
        const text = [p.x, p.y, p.z, t.x, t.y, t.z].map((v) => v.toPrecision(6)).join(',');
        history.replaceState(null, '', `#camera=${text}`);
    });
    window.addEventListener('resize', render);

    const toggles = {};
    const repaint = () => {
        if (segments) paintInput({ patches: toggles.patches.checked, bands: toggles.bands.checked });
        if (edgePoints) edgePoints.visible = toggles.vertices.checked;
        sharpLines.visible = toggles.sharp.checked;
        showWires(toggles.wireframe.checked);
        render();
    };
    for (const name of ['sharp', 'wireframe', 'patches', 'bands', 'vertices']) {
        toggles[name] = document.getElementById(`show-${name}`);
        toggles[name].addEventListener('change', repaint);
        if (!segments && ['patches', 'bands', 'vertices'].includes(name)) toggles[name].disabled = true;
    }

    const builtMs = performance.now();
    document.getElementById('title').textContent = meta.title;
    const palette = { ...meta.colors, sharp_edge: kSharpEdge };
    for (const swatch of document.querySelectorAll('[data-swatch]')) {
        swatch.style.background = `rgb(${palette[swatch.dataset.swatch].join(',')})`;
    }
    buildTable(meta.numbers);
    repaint();
    window.resharpViewer = {
        inputTriangles: inputTriangles.length / 3,
        restoredTriangles: outTriangles.length / 3,
        sharpSegments: sharp.length / 2,
        hasSegments: segments !== null,
        // Milliseconds since navigation started, for the benchmark.
        timing: { parsedMs, decodedMs, builtMs, renderedMs: performance.now() },
    };
    // The next frame's callback runs once the first one has been drawn and shown.
    requestAnimationFrame(() => {
        window.resharpViewer.timing.shownMs = performance.now();
        setStatus('rendered');
    });
}

try {
    main();
} catch (error) {
    setStatus(`error: ${error.message}`);
    throw error;
}
