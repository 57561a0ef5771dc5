// Click-to-inspect (doc/viewer.md): a click (not a drag) on a surface picks
// it, tints it and lists its id, kind, size, area, normal, centre, support
// and tiles in the panel #pmap-inspect. Solid surfaces are picked before
// see-through ones; clicking the same spot again picks the next surface
// behind. A click on nothing, or Escape, clears the selection.
import * as THREE from 'three';
import {surfaceInfo} from './map_surfaces.js';

const CLICK_SLOP_PX = 4;  // a pointer that moved further is a drag (orbit), not a click

function formatNumber(x, digits = 2) {
  return x.toLocaleString('en-US', {minimumFractionDigits: digits, maximumFractionDigits: digits});
}

const vector = (v) => `(${v.map((x) => formatNumber(x)).join(', ')})`;

/** The panel's lines for a surface's info (surfaceInfo). */
export function infoLines(info) {
  const lines = [
    `size: ${formatNumber(info.width_m)} m × ${formatNumber(info.height_m)} m`,
    `area: ${formatNumber(info.area_m2)} m²`,
    `normal: ${vector(info.normal)}`,
    `centre: ${vector(info.centre)} m`,
    `support: ${info.support === null ? 'unknown' : `${info.support.toLocaleString('en-US')} points`}`,
  ];
  if (info.tiles > 1) lines.push(`tiles: ${info.tiles}`);
  return lines;
}

function showPanel(panel, info) {
  panel.replaceChildren();
  if (!info) {
    panel.hidden = true;
    return;
  }
  const title = document.createElement('div');
  title.className = 'pmap-title';
  title.textContent = `surface ${info.id} (${info.kind})`;
  panel.appendChild(title);
  for (const text of infoLines(info)) {
    const line = document.createElement('div');
    line.className = 'pmap-line';
    line.textContent = text;
    panel.appendChild(line);
  }
  const hint = document.createElement('div');
  hint.className = 'pmap-hint';
  hint.textContent = 'click again: the surface behind · Esc: clear';
  panel.appendChild(hint);
  panel.hidden = false;
}

/**
 * Surfaces under the canvas point (CSS pixels), solid ones first, each
 * nearest first, each surface once.
 */
function surfacesAt(x, y, canvas, camera, surfaces) {
  const rect = canvas.getBoundingClientRect();
  const ndc = new THREE.Vector2(((x - rect.left) / rect.width) * 2 - 1,
                                -((y - rect.top) / rect.height) * 2 + 1);
  const raycaster = new THREE.Raycaster();
  raycaster.setFromCamera(ndc, camera);
  const meshes = surfaces.list.flatMap((s) => s.meshes).filter((m) => m.visible);
  const hits = raycaster.intersectObjects(meshes, false).map((hit) => surfaces.byMesh.get(hit.object));
  const ordered = [...hits.filter((s) => !s.seeThrough), ...hits.filter((s) => s.seeThrough)];
  return [...new Set(ordered)];
}

/**
 * Wires picking on `canvas`; `onChange(info | null)` after each change (to
 * re-render). Returns {selected(), pickAt(x, y), clear()}.
 */
export function createInspector(canvas, camera, surfaces, onChange) {
  const panel = document.getElementById('pmap-inspect');
  let selected = null;
  let last = null;  // {x, y, ids, index} of the previous pick
  const select = (surface) => {
    selected = surface ? surfaceInfo(surface) : null;
    surfaces.highlight(surface ? surface.id : null);
    showPanel(panel, selected);
    onChange(selected);
  };
  const pickAt = (x, y) => {
    const stack = surfacesAt(x, y, canvas, camera, surfaces);
    const ids = stack.map((s) => s.id).join(',');
    const again = last && Math.hypot(x - last.x, y - last.y) <= CLICK_SLOP_PX && last.ids === ids;
    const index = stack.length ? (again ? (last.index + 1) % stack.length : 0) : -1;
    last = {x, y, ids, index};
    select(index >= 0 ? stack[index] : null);
  };
  let down = null;
  canvas.addEventListener('pointerdown', (event) => {
    down = event.button === 0 ? {x: event.clientX, y: event.clientY} : null;
  });
  canvas.addEventListener('pointerup', (event) => {
    if (down && Math.hypot(event.clientX - down.x, event.clientY - down.y) <= CLICK_SLOP_PX) {
      pickAt(event.clientX, event.clientY);
    }
    down = null;
  });
  window.addEventListener('keydown', (event) => {
    if (event.key === 'Escape' && selected) select(null);
  });
  return {selected: () => selected, pickAt, clear: () => select(null)};
}
