// Reads the data that libs/viewer embedded in viewer.html: non-executed
// <script type="application/..."> blocks holding JSON or base64 text. Nothing
// is fetched, so the page works when opened from file:// without a network.

/** Text content of the data block `id` ('' when absent). */
function blockText(id) {
  const element = document.getElementById(id);
  return element ? element.textContent.trim() : '';
}

/** Decodes base64 text to bytes (an empty Uint8Array for ''). */
export function base64ToBytes(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/**
 * The page's data: info (the caller's JSON: title and counts), points
 * {total, shown}, glb (ArrayBuffer or null) and positions (Float32Array of
 * x y z triples, z up, metres).
 */
export function readEmbeddedData() {
  const meta = JSON.parse(blockText('pmap-meta') || '{}');
  const glbText = blockText('pmap-glb');
  const pointsText = blockText('pmap-points');
  const glbBytes = glbText ? base64ToBytes(glbText) : null;
  const pointBytes = pointsText ? base64ToBytes(pointsText) : new Uint8Array(0);
  return {
    info: meta.info ?? {},
    points: meta.points ?? {total: 0, shown: 0},
    glb: glbBytes ? glbBytes.buffer : null,
    positions: new Float32Array(pointBytes.buffer, 0, Math.floor(pointBytes.length / 12) * 3),
  };
}
