// Byte fields of the JSON messages: the bridge writes an LCM byte array and
// a Foxglove image's data as base64; the obstacle map's cells may be run-length
// coded and zstd-compressed (lcmtypes/obstacle_map_t.lcm).
import { decompress } from "fzstd";

export const ENCODING_RAW = 0;
export const ENCODING_RLE = 1;
export const ENCODING_RLE_ZSTD = 2;

export function base64Bytes(text) {
  if (typeof text !== "string") return Array.isArray(text) ? Uint8Array.from(text) : new Uint8Array(0);
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

// Pairs (count 1..255, value) expanded into `cells` cells; a short or long
// run list leaves the rest unknown (0) rather than failing.
function runLengthDecode(pairs, cells) {
  const out = new Uint8Array(cells);
  let at = 0;
  for (let i = 0; i + 1 < pairs.length && at < cells; i += 2) {
    const end = Math.min(cells, at + pairs[i]);
    out.fill(pairs[i + 1], at, end);
    at = end;
  }
  return out;
}

// The cells of a map or a rectangle of it, one byte each, row by row.
export function decodeCells(data, encoding, cells) {
  const bytes = base64Bytes(data);
  if (encoding === ENCODING_RAW) return bytes.length === cells ? bytes : runLengthDecode([], cells);
  if (encoding === ENCODING_RLE) return runLengthDecode(bytes, cells);
  if (encoding === ENCODING_RLE_ZSTD) return runLengthDecode(decompress(bytes), cells);
  return runLengthDecode([], cells);
}
