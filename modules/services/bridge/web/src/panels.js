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
export class LogList {
  constructor(list) {
    this.list = list;
    this.count = 0;
  }

  add(entry) {
    const stick = this.list.scrollTop + this.list.clientHeight >= this.list.scrollHeight - 4;
    const level = LOG_LEVEL[entry.level] || "info";
    const seconds = entry.timestamp ? Number(entry.timestamp.sec) + Number(entry.timestamp.nsec) / 1e9 : NaN;
    const line = element("li", `log ${level}`);
    line.append(element("span", "when", when(seconds)), element("span", "who", entry.name || ""), element("span", "what", entry.message || ""));
    this.list.append(line);
    while (this.list.childElementCount > MAX_LOG_LINES) this.list.firstElementChild.remove();
    this.count++;
    if (stick) this.list.scrollTop = this.list.scrollHeight;
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
