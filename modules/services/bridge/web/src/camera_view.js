// The robot's camera images on canvases: foxglove.RawImage (width, height,
// encoding, step, data in base64) or foxglove.CompressedImage (format, data).
import { context2d } from "./canvas_2d.js";
import { base64Bytes } from "./bytes.js";

const BYTES_PER_PIXEL = { rgb8: 3, bgr8: 3, rgba8: 4, bgra8: 4, mono8: 1, "32FC1": 4, "16UC1": 2, mono16: 2 };
const FAR = { "32FC1": 20, "16UC1": 20000, mono16: 20000 };  // depth drawn white near, black at FAR (m or mm)

// The grey level of one depth sample.
function depthSampler(image, bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const little = !image.is_bigendian;
  const far = FAR[image.encoding];
  const read = image.encoding === "32FC1" ? (at) => view.getFloat32(at, little) : (at) => view.getUint16(at, little);
  return (at) => {
    const value = read(at);
    return value > 0 && Number.isFinite(value) ? 255 - Math.min(255, (value / far) * 255) : 0;
  };
}

// RGBA pixels of a raw image, or null for an encoding not handled.
function rawToRgba(image, bytes) {
  const { width, height, encoding } = image;
  const size = BYTES_PER_PIXEL[encoding];
  const rowBytes = image.step || width * size;
  if (!size || bytes.length < rowBytes * (height - 1) + width * size) return null;
  const out = new Uint8ClampedArray(width * height * 4);
  const swap = encoding.startsWith("bgr");
  const depth = FAR[encoding] ? depthSampler(image, bytes) : null;
  for (let r = 0, o = 0; r < height; r++) {
    for (let c = 0, at = r * rowBytes; c < width; c++, at += size, o += 4) {
      if (depth) {
        out[o] = out[o + 1] = out[o + 2] = depth(at);
      } else if (size === 1) {
        out[o] = out[o + 1] = out[o + 2] = bytes[at];
      } else {
        out[o] = bytes[swap ? at + 2 : at];
        out[o + 1] = bytes[at + 1];
        out[o + 2] = bytes[swap ? at : at + 2];
      }
      out[o + 3] = 255;
    }
  }
  return out;
}

export class CameraView {
  constructor(canvas, caption) {
    this.canvas = canvas;
    this.caption = caption;
    this.frames = 0;
    this.busy = false;
  }

  show(image) {
    if (this.busy) return;  // a compressed frame still decoding: skip this one
    const bytes = base64Bytes(image.data);
    if (image.format !== undefined && image.width === undefined) this.showCompressed(image, bytes);
    else this.showRaw(image, bytes);
  }

  showRaw(image, bytes) {
    const rgba = rawToRgba(image, bytes);
    if (!rgba) return this.say(`${image.encoding}: not shown`);
    this.fitCanvas(image.width, image.height);
    context2d(this.canvas).putImageData(new ImageData(rgba, image.width, image.height), 0, 0);
    this.shown(`${image.width}×${image.height} ${image.encoding}`);
  }

  showCompressed(image, bytes) {
    this.busy = true;
    const type = image.format.includes("png") ? "image/png" : "image/jpeg";
    createImageBitmap(new Blob([bytes], { type }))
      .then((bitmap) => {
        this.fitCanvas(bitmap.width, bitmap.height);
        context2d(this.canvas).drawImage(bitmap, 0, 0);
        this.shown(`${bitmap.width}×${bitmap.height} ${image.format}`);
      })
      .catch(() => this.say(`${image.format}: cannot decode`))
      .finally(() => (this.busy = false));
  }

  // Setting a canvas's size, even to the size it has, reallocates its
  // pixels (on the GPU, or in software WebGL's memory): only when it changes.
  fitCanvas(width, height) {
    if (this.canvas.width !== width) this.canvas.width = width;
    if (this.canvas.height !== height) this.canvas.height = height;
  }

  shown(text) {
    this.frames++;
    this.say(text);
  }

  say(text) {
    this.caption.textContent = text;
  }
}
