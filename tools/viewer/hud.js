// The heads-up display: the map's title and counts, the raw-points toggle and
// a hint for the mouse controls. Plain DOM, styled by viewer.template.html.

function addLine(parent, label, value) {
  const line = document.createElement('div');
  line.className = 'pmap-line';
  line.textContent = `${label}: ${value}`;
  parent.appendChild(line);
  return line;
}

function formatValue(value) {
  return typeof value === 'number' ? value.toLocaleString('en-US') : String(value);
}

/**
 * Builds the HUD in #pmap-hud. `info` is the caller's JSON: its "title" heads
 * the HUD, its other scalar entries (surfaces, ...) are listed as counts.
 * Returns {setTriangles(n), pointsCheckbox}.
 */
export function createHud(info, points, onPointsToggled) {
  const hud = document.getElementById('pmap-hud');
  const title = document.createElement('div');
  title.className = 'pmap-title';
  title.textContent = typeof info.title === 'string' ? info.title : 'planar map';
  hud.appendChild(title);
  for (const [key, value] of Object.entries(info)) {
    if (key === 'title' || value === null || typeof value === 'object') continue;
    addLine(hud, key.replace(/_/g, ' '), formatValue(value));
  }
  const triangles = addLine(hud, 'triangles drawn', '-');
  const label = document.createElement('label');
  label.className = 'pmap-toggle';
  const checkbox = document.createElement('input');
  checkbox.type = 'checkbox';
  checkbox.id = 'pmap-points-toggle';
  checkbox.disabled = points.shown === 0;
  checkbox.addEventListener('change', () => onPointsToggled(checkbox.checked));
  label.append(checkbox, ` raw points (${formatValue(points.shown)} of ${formatValue(points.total)})`);
  hud.appendChild(label);
  const hint = document.createElement('div');
  hint.className = 'pmap-hint';
  hint.textContent = 'drag: rotate · right-drag: pan · wheel: zoom';
  hud.appendChild(hint);
  return {
    setTriangles: (n) => { triangles.textContent = `triangles drawn: ${formatValue(n)}`; },
    pointsCheckbox: checkbox,
  };
}
