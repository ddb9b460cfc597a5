// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_VIEWER_PAGE_H
#define CGAL_QD_IO_INTERNAL_VIEWER_PAGE_H

// The fixed parts of the page that IO::write_viewer_HTML() writes: its style,
// and the script that draws the data of the page with three.js (the global
// THREE of its UMD build). The script reads the JSON in the element
// #qd-data, renders the mesh (left) and the flattened pieces (right) on
// demand, and highlights a piece or a seam on both sides under the pointer
// (the piece ids are drawn into an offscreen buffer once per camera position).
// For tests, <body> gets data-status="ready" once both sides are drawn, and
// data-errors with the number of errors and console errors seen.

namespace CGAL_QD {
namespace internal {

inline const char* viewer_style()
{
  return R"QD(
html, body { margin: 0; height: 100%; font: 14px/1.35 system-ui, sans-serif; color: #222; background: #fff; }
#bar { height: 34px; display: flex; align-items: center; gap: 16px; padding: 0 12px; border-bottom: 1px solid #ddd; }
#bar b { font-size: 15px; }
#bar span { color: #666; }
#views { position: absolute; top: 35px; bottom: 0; left: 0; right: 0; display: flex; }
#left, #right { position: relative; flex: 1; overflow: hidden; }
#left { border-right: 1px solid #ddd; }
canvas { display: block; touch-action: none; }
.caption { position: absolute; left: 10px; top: 8px; color: #555; pointer-events: none; }
#info { position: absolute; right: 12px; top: 45px; min-width: 220px; max-width: 320px; padding: 8px 10px;
        background: rgba(255, 255, 255, 0.92); border: 1px solid #ccc; border-radius: 4px; pointer-events: none; }
#info:empty { display: none; }
#info table { border-collapse: collapse; }
#info td { padding: 0 8px 0 0; }
#scale { position: absolute; right: 14px; bottom: 12px; text-align: right; color: #333; pointer-events: none; }
#scale div { height: 6px; border: 2px solid #333; border-top: none; margin-left: auto; }
)QD";
}

inline const char* viewer_script()
{
  return R"QD(
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('qd-data').textContent);
  function decode(text, Type) {
    const bin = atob(text), bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) bytes[i] = bin.charCodeAt(i);
    return new Type(bytes.buffer);
  }
  const P = decode(data.positions, Float32Array), T = decode(data.triangles, Uint32Array);
  const FC = decode(data.face_chart, Uint32Array), FL = decode(data.flat, Float32Array);
  const S3 = decode(data.seam_edges_3d, Float32Array), S3id = decode(data.seam_ids_3d, Int32Array);
  const S2 = decode(data.seam_edges_2d, Float32Array), S2id = decode(data.seam_ids_2d, Int32Array);
  const m = FC.length, n = data.charts.length;

  // ---- the chart colours, as a texture of n texels
  const texWidth = Math.min(Math.max(n, 1), 1024), texHeight = Math.max(1, Math.ceil(n / 1024));
  const texels = new Uint8Array(4 * texWidth * texHeight);
  data.palette.forEach(function (hex, k) {
    const v = parseInt(hex.slice(1), 16);
    texels.set([(v >> 16) & 255, (v >> 8) & 255, v & 255, 255], 4 * k);
  });
  const palette = new THREE.DataTexture(texels, texWidth, texHeight, THREE.RGBAFormat);
  palette.magFilter = palette.minFilter = THREE.NearestFilter;
  palette.needsUpdate = true;

  const vertexShader = [
    'attribute float chart;', 'varying float vChart;', 'varying vec3 vView;',
    'void main() {', '  vChart = chart;', '  vec4 mv = modelViewMatrix * vec4(position, 1.0);',
    '  vView = mv.xyz;', '  gl_Position = projectionMatrix * mv;', '}'].join('\n');
  const chartShader = [
    'uniform sampler2D uPalette;', 'uniform vec2 uSize;', 'uniform float uLit;',
    'uniform float uChart;', 'uniform float uPairA;', 'uniform float uPairB;',
    'varying float vChart;', 'varying vec3 vView;',
    'void main() {',
    '  float id = floor(vChart + 0.5);',
    '  vec2 at = vec2((mod(id, uSize.x) + 0.5) / uSize.x, (floor(id / uSize.x) + 0.5) / uSize.y);',
    '  vec3 c = texture2D(uPalette, at).rgb;',
    '  if (uLit > 0.5) {',
    '    vec3 nrm = normalize(cross(dFdx(vView), dFdy(vView)));',
    '    c *= 0.4 + 0.6 * abs(nrm.z);',
    '  }',
    '  bool chosen = abs(id - uChart) < 0.5 || abs(id - uPairA) < 0.5 || abs(id - uPairB) < 0.5;',
    '  bool any = uChart >= 0.0 || uPairA >= 0.0;',
    '  if (any && !chosen) c = mix(c, vec3(0.82), 0.7);',
    '  gl_FragColor = vec4(c, 1.0);',
    '}'].join('\n');
  const pickShader = [
    'varying float vChart;', 'varying vec3 vView;',
    'void main() {',
    '  float v = floor(vChart + 0.5) + 1.0;',
    '  gl_FragColor = vec4(mod(v, 256.0) / 255.0, mod(floor(v / 256.0), 256.0) / 255.0, floor(v / 65536.0) / 255.0, 1.0);',
    '}'].join('\n');
  const lineVertex = [
    'attribute float seam;', 'varying float vSeam;',
    'void main() {', '  vSeam = seam;', '  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);', '}'
  ].join('\n');
  const lineShader = [
    'uniform float uSeam;', 'varying float vSeam;',
    'void main() {',
    '  if (abs(vSeam - uSeam) < 0.5) gl_FragColor = vec4(0.85, 0.1, 0.1, 1.0);',
    '  else gl_FragColor = vec4(0.12, 0.12, 0.12, 1.0);',
    '}'].join('\n');

  // the highlighted seam also as round dots at its vertices: a line is one pixel wide in WebGL
  const dotVertex = [
    'attribute float seam;', 'uniform float uSeam;', 'varying float vSeam;',
    'void main() {', '  vSeam = seam;', '  gl_PointSize = abs(seam - uSeam) < 0.5 ? 7.0 : 0.0;',
    '  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);', '}'].join('\n');
  const dotShader = [
    'uniform float uSeam;', 'varying float vSeam;',
    'void main() {',
    '  vec2 d = gl_PointCoord - vec2(0.5);',
    '  if (abs(vSeam - uSeam) > 0.5 || dot(d, d) > 0.25) discard;',
    '  gl_FragColor = vec4(0.85, 0.1, 0.1, 1.0);',
    '}'].join('\n');
  function chartMaterial(lit) {
    return new THREE.ShaderMaterial({
      uniforms: { uPalette: { value: palette }, uSize: { value: new THREE.Vector2(texWidth, texHeight) },
                  uLit: { value: lit ? 1 : 0 }, uChart: { value: -1 }, uPairA: { value: -1 }, uPairB: { value: -1 } },
      vertexShader: vertexShader, fragmentShader: chartShader, side: THREE.DoubleSide,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
      extensions: { derivatives: true }
    });
  }
  function lineMaterial() {
    return new THREE.ShaderMaterial({ uniforms: { uSeam: { value: -1 } }, vertexShader: lineVertex,
                                      fragmentShader: lineShader });
  }
  // one corner per face corner, so that every face keeps its chart
  function faceGeometry(position) {
    const g = new THREE.BufferGeometry(), chart = new Float32Array(3 * m);
    for (let f = 0; f < m; ++f) chart[3 * f] = chart[3 * f + 1] = chart[3 * f + 2] = FC[f];
    g.setAttribute('position', new THREE.BufferAttribute(position, 3));
    g.setAttribute('chart', new THREE.BufferAttribute(chart, 1));
    g.computeBoundingSphere();
    return g;
  }
  function lineGeometry(position, ids) {
    const g = new THREE.BufferGeometry(), seam = new Float32Array(ids.length * 2);
    for (let i = 0; i < ids.length; ++i) seam[2 * i] = seam[2 * i + 1] = ids[i];
    g.setAttribute('position', new THREE.BufferAttribute(position, 3));
    g.setAttribute('seam', new THREE.BufferAttribute(seam, 1));
    return g;
  }
  const pos3 = new Float32Array(9 * m), pos2 = new Float32Array(9 * m);
  for (let f = 0; f < m; ++f)
    for (let k = 0; k < 3; ++k) {
      const v = T[3 * f + k];
      pos3.set([P[3 * v], P[3 * v + 1], P[3 * v + 2]], 9 * f + 3 * k);
      pos2.set([FL[6 * f + 2 * k], FL[6 * f + 2 * k + 1], 0], 9 * f + 3 * k);
    }
  function segments(flat, dim) {  // [x0 y0 (z0) x1 y1 (z1)] per segment -> 3D positions
    const count = flat.length / (2 * dim), out = new Float32Array(6 * count);
    for (let i = 0; i < count; ++i)
      for (let e = 0; e < 2; ++e)
        for (let c = 0; c < 3; ++c) out[6 * i + 3 * e + c] = c < dim ? flat[2 * dim * i + dim * e + c] : 0;
    return out;
  }

  function makeView(container, lit, geometry, lines) {
    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xffffff, 1);
    container.appendChild(renderer.domElement);
    const scene = new THREE.Scene(), pickScene = new THREE.Scene();
    const material = chartMaterial(lit), lineMat = lineMaterial();
    scene.add(new THREE.Mesh(geometry, material));
    scene.add(new THREE.LineSegments(lines, lineMat));
    const dotMat = new THREE.ShaderMaterial({ uniforms: { uSeam: lineMat.uniforms.uSeam }, vertexShader: dotVertex,
                                              fragmentShader: dotShader, depthTest: lit });
    scene.add(new THREE.Points(lines, dotMat));
    pickScene.add(new THREE.Mesh(geometry, new THREE.ShaderMaterial({
      vertexShader: vertexShader, fragmentShader: pickShader, side: THREE.DoubleSide })));
    return { container: container, renderer: renderer, scene: scene, pickScene: pickScene, material: material,
             lineMaterial: lineMat, target: new THREE.WebGLRenderTarget(1, 1), camera: null, pickKey: '',
             pickIds: null };
  }

  const left = makeView(document.getElementById('left'), true, faceGeometry(pos3), lineGeometry(segments(S3, 3), S3id));
  const right = makeView(document.getElementById('right'), false, faceGeometry(pos2), lineGeometry(segments(S2, 2), S2id));
  left.camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
  right.camera = new THREE.OrthographicCamera(-1, 1, 1, -1, -10, 10);

  // ---- the 3D view orbits the mesh's centre (the data is centred and scaled to a unit box)
  const orbit = { azimuth: data.view.azimuth, elevation: data.view.elevation, distance: 2.6 };
  function placeLeftCamera() {
    const ca = Math.cos(orbit.azimuth), sa = Math.sin(orbit.azimuth);
    const ce = Math.cos(orbit.elevation), se = Math.sin(orbit.elevation);
    left.camera.position.set(-sa * ce * orbit.distance, se * orbit.distance, ca * ce * orbit.distance);
    left.camera.up.set(0, 1, 0);
    left.camera.lookAt(0, 0, 0);
  }
  // ---- the 2D view: the pieces' box fitted, then panned and zoomed
  const flatBox = new THREE.Box3().setFromBufferAttribute(new THREE.BufferAttribute(pos2, 3));
  const flatView = { x: (flatBox.min.x + flatBox.max.x) / 2, y: (flatBox.min.y + flatBox.max.y) / 2,
                     half: 0.55 * Math.max(flatBox.max.x - flatBox.min.x, flatBox.max.y - flatBox.min.y, 1e-9) };
  function placeRightCamera() {
    const w = right.container.clientWidth || 1, h = right.container.clientHeight || 1, a = w / h;
    const hx = a >= 1 ? flatView.half * a : flatView.half, hy = a >= 1 ? flatView.half : flatView.half / a;
    Object.assign(right.camera, { left: flatView.x - hx, right: flatView.x + hx, top: flatView.y + hy,
                                  bottom: flatView.y - hy });
    right.camera.updateProjectionMatrix();
    // the scale bar: a round length in mesh units
    const perPixel = 2 * hx / w * data.extent;
    let length = Math.pow(10, Math.floor(Math.log10(perPixel * 120)));
    if (length * 5 / perPixel <= 160) length *= 5; else if (length * 2 / perPixel <= 160) length *= 2;
    const bar = document.getElementById('scale');
    let text = format(length) + ' (mesh units)';
    if (data.pattern_scale > 0) text += ' = ' + format(length * data.pattern_scale) + ' ' + data.pattern_units + ' on the pattern';
    bar.innerHTML = '<div style="width:' + (length / perPixel).toFixed(1) + 'px"></div>' + text;
  }
  function resize() {
    for (const v of [left, right]) {
      const w = v.container.clientWidth || 1, h = v.container.clientHeight || 1;
      v.renderer.setSize(w, h);
    }
    left.camera.aspect = (left.container.clientWidth || 1) / (left.container.clientHeight || 1);
    left.camera.updateProjectionMatrix();
    placeRightCamera();
    requestDraw();
  }
  let drawPending = false;
  function requestDraw() {
    if (drawPending) return;
    drawPending = true;
    requestAnimationFrame(draw);
  }
  function draw() {
    drawPending = false;
    placeLeftCamera();
    for (const v of [left, right]) v.renderer.render(v.scene, v.camera);
    if (document.body.dataset.status !== 'ready') document.body.dataset.status = 'ready';
  }

  // ---- what is under the pointer: a piece, read from the piece ids drawn into
  // a buffer of the view's size once per camera position (so pointing costs
  // nothing until the view turns, moves or zooms), or a seam within 6 pixels
  function pickChart(v, x, y) {
    const w = v.container.clientWidth, h = v.container.clientHeight;
    const key = w + ' ' + h + ' ' + v.camera.matrixWorld.elements.join(' ') + ' ' +
                v.camera.projectionMatrix.elements.join(' ');
    if (v.pickKey !== key) {
      v.pickKey = key;
      v.target.setSize(w, h);
      v.renderer.setRenderTarget(v.target);
      v.renderer.setClearColor(0x000000, 1);
      v.renderer.clear();
      v.renderer.render(v.pickScene, v.camera);
      v.pickIds = new Uint8Array(4 * w * h);
      v.renderer.readRenderTargetPixels(v.target, 0, 0, w, h, v.pickIds);
      v.renderer.setRenderTarget(null);
      v.renderer.setClearColor(0xffffff, 1);
    }
    x = Math.floor(x);
    y = Math.floor(y);
    if (x < 0 || y < 0 || x >= w || y >= h) return -1;
    const at = 4 * ((h - 1 - y) * w + x), ids = v.pickIds;
    const id = ids[at] + 256 * ids[at + 1] + 65536 * ids[at + 2] - 1;
    return id >= 0 && id < n ? id : -1;
  }
  const projected = new THREE.Vector3();
  function pickSeam(v, positions, ids, x, y, chart) {
    const w = v.container.clientWidth, h = v.container.clientHeight;
    let best = -1, bestDistance = 36;
    const a = [0, 0], b = [0, 0];
    for (let i = 0; i < ids.length; ++i) {
      const s = data.seams[ids[i]];
      if (chart >= 0 && s.charts[0] !== chart && s.charts[1] !== chart) continue;
      for (let e = 0; e < 2; ++e) {
        projected.set(positions[6 * i + 3 * e], positions[6 * i + 3 * e + 1], positions[6 * i + 3 * e + 2]).project(v.camera);
        const q = e ? b : a;
        q[0] = (projected.x + 1) / 2 * w;
        q[1] = (1 - projected.y) / 2 * h;
      }
      const dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
      const t = l2 > 0 ? Math.max(0, Math.min(1, ((x - a[0]) * dx + (y - a[1]) * dy) / l2)) : 0;
      const ex = a[0] + t * dx - x, ey = a[1] + t * dy - y, d = ex * ex + ey * ey;
      if (d < bestDistance) { bestDistance = d; best = ids[i]; }
    }
    return best;
  }
  const lines3 = left.scene.children[1].geometry.attributes.position.array;
  const lines2 = right.scene.children[1].geometry.attributes.position.array;
  let hovered = { chart: -1, seam: -1 }, pinned = null;
  function pick(v, x, y) {
    const chart = pickChart(v, x, y);
    const seam = pickSeam(v, v === left ? lines3 : lines2, v === left ? S3id : S2id, x, y, chart);
    return seam >= 0 ? { chart: -1, seam: seam } : { chart: chart, seam: -1 };
  }
  function format(x) {
    if (!isFinite(x)) return String(x);
    const a = Math.abs(x);
    return a !== 0 && (a < 1e-3 || a >= 1e6) ? x.toExponential(3) : String(Number(x.toPrecision(4)));
  }
  function show(sel) {
    const seam = sel.seam >= 0 ? data.seams[sel.seam] : null;
    for (const v of [left, right]) {
      v.material.uniforms.uChart.value = sel.chart;
      v.material.uniforms.uPairA.value = seam ? seam.charts[0] : -1;
      v.material.uniforms.uPairB.value = seam ? seam.charts[1] : -1;
      v.lineMaterial.uniforms.uSeam.value = sel.seam;
    }
    const info = document.getElementById('info');
    const unit = data.pattern_scale > 0 ? data.pattern_units : '';
    const onPattern = function (l) { return unit ? ' (' + format(l * data.pattern_scale) + ' ' + unit + ')' : ''; };
    if (sel.chart >= 0) {
      const c = data.charts[sel.chart];
      info.innerHTML = '<b>Piece ' + sel.chart + '</b> (' + c.faces + ' faces)<table>' +
        '<tr><td>area</td><td>' + format(c.area) + (unit ? ' (' + format(c.area * data.pattern_scale * data.pattern_scale) +
        ' ' + unit + '\u00b2)' : '') + '</td></tr>' +
        '<tr><td>A(\u03a9)</td><td>' + format(c.area_distortion_pct) + ' %</td></tr>' +
        '<tr><td>L\u00b2</td><td>' + format(c.l2_stretch) + '</td></tr>' +
        '<tr><td>A_loc</td><td>' + format(c.local_area_distortion_pct) + ' %</td></tr>' +
        (c.accepted ? '' : '<tr><td colspan="2">beyond the thresholds</td></tr>') + '</table>';
    } else if (seam) {
      info.innerHTML = '<b>Seam ' + seam.label + '</b> ' + (seam.charts[0] === seam.charts[1]
        ? 'a cut inside piece ' + seam.charts[0] : 'between pieces ' + seam.charts[0] + ' and ' + seam.charts[1]) +
        '<table><tr><td>length</td><td>' + format(seam.length) + onPattern(seam.length) + '</td></tr>' +
        '<tr><td>sides, flat</td><td>' + format(seam.sides[0]) + ' and ' + format(seam.sides[1]) + '</td></tr></table>';
    } else {
      info.innerHTML = '';
    }
    requestDraw();
  }

  // ---- the pointer: drag to turn (left) or pan (right), wheel to zoom, click to pin a piece or a seam
  function attach(v) {
    const el = v.renderer.domElement;
    let drag = null;
    el.addEventListener('contextmenu', function (e) { e.preventDefault(); });
    el.addEventListener('pointerdown', function (e) {
      drag = { x: e.clientX, y: e.clientY, moved: false };
      el.setPointerCapture(e.pointerId);
    });
    el.addEventListener('pointerup', function (e) {
      if (drag && !drag.moved) {
        const r = el.getBoundingClientRect(), sel = pick(v, e.clientX - r.left, e.clientY - r.top);
        pinned = sel.chart < 0 && sel.seam < 0 ? null : sel;
        show(pinned || sel);
      }
      drag = null;
    });
    el.addEventListener('pointermove', function (e) {
      const r = el.getBoundingClientRect();
      if (drag) {
        const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
        if (Math.abs(dx) + Math.abs(dy) > 2) drag.moved = true;
        if (!drag.moved) return;
        drag.x = e.clientX;
        drag.y = e.clientY;
        if (v === left && e.buttons === 1 && !e.shiftKey) {
          orbit.azimuth -= dx * 0.008;
          orbit.elevation = Math.max(-1.55, Math.min(1.55, orbit.elevation + dy * 0.008));
        } else if (v === right) {
          const unitsPerPixel = (right.camera.right - right.camera.left) / r.width;
          flatView.x -= dx * unitsPerPixel;
          flatView.y += dy * unitsPerPixel;
          placeRightCamera();
        }
        requestDraw();
        return;
      }
      if (pinned) return;
      const sel = pick(v, e.clientX - r.left, e.clientY - r.top);
      if (sel.chart !== hovered.chart || sel.seam !== hovered.seam) {
        hovered = sel;
        show(sel);
      }
    });
    el.addEventListener('pointerleave', function () {
      if (!pinned && (hovered.chart >= 0 || hovered.seam >= 0)) {
        hovered = { chart: -1, seam: -1 };
        show(hovered);
      }
    });
    el.addEventListener('wheel', function (e) {
      e.preventDefault();
      const factor = Math.exp(0.0015 * e.deltaY);
      if (v === left) orbit.distance = Math.max(0.2, Math.min(20, orbit.distance * factor));
      else {
        flatView.half = Math.max(1e-6, flatView.half * factor);
        placeRightCamera();
      }
      requestDraw();
    }, { passive: false });
  }
  attach(left);
  attach(right);
  window.addEventListener('resize', resize);
  document.body.dataset.charts = String(n);
  document.body.dataset.palette = data.palette.join(' ');
  resize();
})();
)QD";
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_VIEWER_PAGE_H
