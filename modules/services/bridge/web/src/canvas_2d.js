// A canvas's 2-D context drawn by the CPU in the page's own process. The
// page's 2-D canvases are small and drawn a few times a second: drawn by the
// GPU process instead (Chromium's default), every drawing is a round trip
// to it and, where the browser draws in software (SwiftShader), costs more
// of the CPU than drawing it here. willReadFrequently is how a page asks for
// that (HTML's canvas settings).
export function context2d(canvas) {
  return canvas.getContext("2d", { willReadFrequently: true });
}
