// The side panels in text: the task stack, the processes' log lines and the
// Petri net's marking.

const TASK_STATUS = ["pending", "active", "suspended", "done", "failed"];
const LOG_LEVEL = { 0: "unknown", 1: "debug", 2: "info", 3: "warning", 4: "error", 5: "fatal" };
const MAX_LOG_LINES = 500;

function element(tag, className, text) {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

function number(value, digits = 1) {
  return Number.isFinite(value) ? value.toFixed(digits) : "–";
}

// Wall-clock times (the processes' log) as the time of day, UTC; run times in seconds.
function when(seconds) {
  if (!Number.isFinite(seconds)) return "";
  return seconds > 1e8 ? new Date(seconds * 1000).toISOString().slice(11, 21) : number(seconds, 1);
}

export function showTaskStack(list, message) {
  const tasks = message.tasks || [];
  list.replaceChildren(
    ...tasks.map((task) => {
      const where = task.object_id ? task.object_id : `(${number(task.x)}, ${number(task.y)})`;
      const status = TASK_STATUS[task.status] || String(task.status);
      const item = element("li", `task ${status}`);
      item.append(element("span", "kind", task.kind), ` ${where} `, element("span", "status", status));
      item.title = `${task.note || ""} (from ${task.origin || "?"}, priority ${task.priority})`;
      return item;
    }),
  );
  if (!tasks.length) list.replaceChildren(element("li", "empty", "empty"));
}

// foxglove.Log: {timestamp: {sec, nsec}, level, message, name, file, line}.
// Lines are taken as they come and put on the page by draw(), in one batch:
// a run at full speed logs hundreds of lines a second, and laying the page
// out for each would take a core from the run beside it.
export class LogList {
  constructor(list) {
    this.list = list;
    this.count = 0;
    this.pending = [];
  }

  add(entry) {
    this.pending.push(entry);
    if (this.pending.length > 2 * MAX_LOG_LINES) this.pending.splice(0, this.pending.length - MAX_LOG_LINES);
    this.count++;
  }

  draw() {
    if (!this.pending.length) return;
    const stick = this.list.scrollTop + this.list.clientHeight >= this.list.scrollHeight - 4;
    const lines = document.createDocumentFragment();
    for (const entry of this.pending.slice(-MAX_LOG_LINES)) lines.append(logLine(entry));
    this.pending = [];
    this.list.append(lines);
    while (this.list.childElementCount > MAX_LOG_LINES) this.list.firstElementChild.remove();
    if (stick) this.list.scrollTop = this.list.scrollHeight;
  }
}

function logLine(entry) {
  const level = LOG_LEVEL[entry.level] || "info";
  const seconds = entry.timestamp ? Number(entry.timestamp.sec) + Number(entry.timestamp.nsec) / 1e9 : NaN;
  const line = element("li", `log ${level}`);
  line.append(element("span", "when", when(seconds)), element("span", "who", entry.name || ""), element("span", "what", entry.message || ""));
  return line;
}

// A panel drawn from the newest message it was given (the task stack, the
// marking: each message holds the whole state), once, when the page draws.
export class LatestMessagePanel {
  constructor(drawMessage) {
    this.drawMessage = drawMessage;
    this.pending = null;
  }

  set(message) {
    this.pending = message;
  }

  draw() {
    if (this.pending === null) return;
    const message = this.pending;
    this.pending = null;
    this.drawMessage(message);
  }
}

// MARKING: every place with its tokens, the experts firing now lit.
export function showMarking(box, message) {
  const places = message.place_ids || [];
  const tokens = message.tokens || [];
  const marked = element("div", "places");
  places.forEach((place, i) => {
    const chip = element("span", tokens[i] > 0 ? "place marked" : "place", place);
    if (tokens[i] > 0) chip.append(element("b", "tokens", tokens[i] > 1 ? ` ${"●".repeat(Math.min(tokens[i], 5))}` : " ●"));
    marked.append(chip);
  });
  const running = element("div", "running");
  running.append(element("span", "caption", "firing: "));
  for (const expert of message.running || []) running.append(element("span", "transition lit", expert));
  if (!(message.running || []).length) running.append(element("span", "transition", "none"));
  const event = element("div", "event", `step ${message.step}: ${message.event || ""}`);
  box.replaceChildren(event, running, marked);
}
