// The run's Petri net as `beft net draw` lays it out (Graphviz's SVG, which
// the bridge serves when it knows the run's net: serverInfo's metadata
// "net"), with each MARKING lit on it: marked places filled and their tokens
// counted, the transitions of the experts firing now highlighted. Without a
// drawing the marking is listed instead (panels.js).
const SVG_NS = "http://www.w3.org/2000/svg";
const PLACE_PREFIX = "place:";
const EXPERT_CLASS = "expert-";

// The SVG element of a drawing, or null for anything that is not one.
function parseSvg(text) {
  const doc = new DOMParser().parseFromString(text, "image/svg+xml");
  const root = doc.documentElement;
  if (!root || root.localName !== "svg" || doc.getElementsByTagName("parsererror").length) return null;
  // Scripts and event handlers have no place in a drawing of a net.
  for (const node of root.querySelectorAll("script, foreignObject")) node.remove();
  for (const node of root.querySelectorAll("*"))
    for (const attribute of [...node.attributes]) if (attribute.name.startsWith("on")) node.removeAttribute(attribute.name);
  root.removeAttribute("width");   // the panel's width, the drawing's proportions
  root.removeAttribute("height");
  return root;
}

// The token count of a place, drawn at the centre of its circle.
function tokenLabel(group) {
  let label = group.querySelector("text.tokens");
  if (label) return label;
  const circle = group.querySelector("ellipse");
  if (!circle) return null;
  label = document.createElementNS(SVG_NS, "text");
  label.setAttribute("class", "tokens");
  label.setAttribute("x", circle.getAttribute("cx"));
  label.setAttribute("y", String(Number(circle.getAttribute("cy")) + 4));
  label.setAttribute("text-anchor", "middle");
  group.append(label);
  return label;
}

// Place id -> tokens of a MARKING.
function placeTokens(message) {
  const tokens = new Map();
  (message.place_ids || []).forEach((id, i) => tokens.set(id, (message.tokens || [])[i] || 0));
  return tokens;
}

export class NetDrawing {
  constructor(box, state) {
    this.box = box;
    this.state = state;
    this.places = new Map();  // place id -> <g>
    this.transitions = [];    // [{group, expert}]
    this.lastMarking = null;
    this.markingDrawn = false;
    box.addEventListener("click", () => box.classList.toggle("expanded"));
  }

  // Fetches the drawing at `path` (same origin); false when there is none.
  async load(path) {
    if (typeof path !== "string" || !path.startsWith("/")) return false;
    const response = await fetch(path, { cache: "no-store" });
    if (!response.ok) return false;
    const svg = parseSvg(await response.text());
    if (!svg) return false;
    const drawing = document.importNode(svg, true);
    drawing.classList.add("net-drawing");
    this.places.clear();
    for (const group of drawing.querySelectorAll("g.place")) this.places.set(group.id.slice(PLACE_PREFIX.length), group);
    this.transitions = [...drawing.querySelectorAll("g.transition")].map((group) => {
      const name = [...group.classList].find((c) => c.startsWith(EXPERT_CLASS));
      return { group, expert: name ? name.slice(EXPERT_CLASS.length) : "" };
    });
    this.box.replaceChildren(drawing);
    this.state.netDrawn = true;
    if (this.lastMarking) this.show(this.lastMarking);
    this.draw();
    return true;
  }

  // Takes a MARKING: the page's state (what is lit and marked) follows every
  // one; the drawing is lit by draw(), on the page's panel cadence.
  show(message) {
    this.lastMarking = message;
    this.markingDrawn = false;
    if (!this.state.netDrawn) return false;
    const running = new Set(message.running || []);
    const lit = this.transitions.filter(({ expert }) => expert !== "" && running.has(expert)).map((t) => t.expert);
    this.state.netLit = lit;
    for (const expert of lit) if (!this.state.netLitSeen.includes(expert)) this.state.netLitSeen.push(expert);
    const tokens = placeTokens(message);
    this.state.netMarked = [...this.places.keys()].filter((id) => (tokens.get(id) || 0) > 0);
    return true;
  }

  // Lights the last MARKING on the drawing, once.
  draw() {
    const message = this.lastMarking;
    if (!message || this.markingDrawn || !this.state.netDrawn) return;
    this.markingDrawn = true;
    const tokens = placeTokens(message);
    for (const [id, group] of this.places) {
      const count = tokens.get(id) || 0;
      group.classList.toggle("marked", count > 0);
      const label = tokenLabel(group);
      if (label) label.textContent = count > 0 ? (count > 4 ? String(count) : "\u25CF".repeat(count)) : "";
    }
    const running = new Set(message.running || []);
    for (const { group, expert } of this.transitions) group.classList.toggle("lit", expert !== "" && running.has(expert));
  }
}
