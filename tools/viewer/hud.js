// The heads-up display: the map's title and counts, the toggles (raw points,
// ceilings, see-through outer sides, robot path), the "frame all" button and a
// hint for the mouse. Plain DOM, styled by viewer.template.html.

function addLine(parent, label, value, before = null) {
  const line = document.createElement('div');
  line.className = 'pmap-line';
  line.textContent = `${label}: ${value}`;
  parent.insertBefore(line, before);
  return line;
}

export function formatValue(value) {
  return typeof value === 'number' ? value.toLocaleString('en-US') : String(value);
}

/**
 * Builds the HUD in #pmap-hud. `info` is the caller's JSON: its "title" heads
 * the HUD, its other scalar entries (surfaces, ...) are listed as counts.
 * Returns {addLine(label, value), addToggle(...), addButton(...), addHint(text),
 * setTriangles(n)}; controls appear in the order they are added.
 */
export function createHud(info) {
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
  const controls = document.createElement('div');
  controls.className = 'pmap-controls';
  hud.appendChild(controls);
  return {
    /** A "label: value" line after the counts (before the controls). */
    addLine: (label, value) => addLine(hud, label, value, controls),
    /** A checkbox `id` labelled `text`; onChange(checked). Returns the checkbox. */
    addToggle(id, text, {checked = false, disabled = false, title = ''}, onChange) {
      const label = document.createElement('label');
      label.className = 'pmap-toggle';
      label.title = title;
      const checkbox = document.createElement('input');
      checkbox.type = 'checkbox';
      checkbox.id = id;
      checkbox.checked = checked;
      checkbox.disabled = disabled;
      checkbox.addEventListener('change', () => onChange(checkbox.checked));
      label.append(checkbox, ` ${text}`);
      controls.appendChild(label);
      return checkbox;
    },
    /** A button `id` labelled `text`; onClick(). Returns the button. */
    addButton(id, text, title, onClick) {
      const button = document.createElement('button');
      button.type = 'button';
      button.id = id;
      button.className = 'pmap-button';
      button.textContent = text;
      button.title = title;
      button.addEventListener('click', onClick);
      controls.appendChild(button);
      return button;
    },
    addHint(text) {
      const hint = document.createElement('div');
      hint.className = 'pmap-hint';
      hint.textContent = text;
      hud.appendChild(hint);
    },
    setTriangles: (n) => { triangles.textContent = `triangles drawn: ${formatValue(n)}`; },
  };
}
