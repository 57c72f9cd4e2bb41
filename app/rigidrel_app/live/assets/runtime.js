// rigidrel's playback runtime: a tab's animation plays here, in the browser, from data the server
// sent once per state (rigidrel_app/live/timeline.py writes it; its docstring has the format).
//
// The server sends it (run by viser's RunJavascriptMessage) with __CONFIG__ replaced by
// {owner, report, clock}: the owner id the tab's scene messages carry, the id of the hidden text
// box this runtime reports through, and the ids of the time controls it keeps up to date.
// It finds viser's viewer in React's fiber tree, takes the server's "PlaybackMessage"s out of
// viser's message queue, and each animation frame pushes that frame's scene updates into the
// same queue (what the server would have sent), then asks viser to render. Everything it reaches
// in viser's client is listed in rigidrel_app/backends/_viser.py.
(() => {
  "use strict";
  const CONFIG = __CONFIG__;
  const FRAME_RATE = CONFIG.frameRate; // timeline frames per second of playback at speed 1
  const CLOCK_HZ = 10; // the time controls follow playback at this rate
  const POINTER_MS = 50; // a drag is reported at most this often (as viser sends a dragged slider)
  const POINTER_EVENTS = 16; // a report carries the latest this many pointer events
  const win = window;
  if (win.__rigidrelPlayback) win.__rigidrelPlayback.dispose();

  // ------------------------------------------------------------------ viser's viewer
  function isViewer(value) {
    return !!value && typeof value === "object" && !!value.mutable && "useSceneTree" in value && "useGuiConfig" in value;
  }
  function findViewer() {
    const root = document.getElementById("root");
    if (!root) return null;
    const key = Object.keys(root).find((k) => k.startsWith("__reactContainer$"));
    const stack = key ? [root[key]] : [];
    const seen = new Set();
    while (stack.length) {
      const fiber = stack.pop();
      if (!fiber || seen.has(fiber)) continue;
      seen.add(fiber);
      const value = fiber.memoizedProps && fiber.memoizedProps.value;
      if (isViewer(value)) return value;
      if (fiber.child) stack.push(fiber.child);
      if (fiber.sibling) stack.push(fiber.sibling);
    }
    return null;
  }

  // ------------------------------------------------------------------ payloads
  const DTYPES = {
    "<f2": Uint16Array, "<f4": Float32Array, "<f8": Float64Array, "|u1": Uint8Array, "<u2": Uint16Array,
    "<u4": Uint32Array, "|i1": Int8Array, "<i2": Int16Array, "<i4": Int32Array,
  };
  async function inflate(bytes) {
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
    return await new Response(stream).arrayBuffer();
  }
  function view(buf, base, spans, index, Ctor) {
    const [offset, length] = spans[index];
    return new Ctor(buf, base + offset, length / Ctor.BYTES_PER_ELEMENT);
  }
  // viser's binary placeholders {"__binary_index": i, "dtype": ...} as typed arrays of their dtype
  function arrays(value, buf, base, spans) {
    if (value === null || typeof value !== "object") return value;
    if (Array.isArray(value)) return value.map((v) => arrays(v, buf, base, spans));
    if ("__binary_index" in value && "dtype" in value) {
      return view(buf, base, spans, value.__binary_index, DTYPES[value.dtype] || Uint8Array);
    }
    const out = {};
    for (const k of Object.keys(value)) out[k] = arrays(value[k], buf, base, spans);
    return out;
  }
  // one column's value at each frame of the block
  function columnValues(c, count, buf, base, spans) {
    if (c.kind === "table") {
      const index = view(buf, base, spans, c.index, Uint32Array);
      const table = c.values.map((v) => arrays(v, buf, base, spans));
      return Array.from(index, (i) => table[i]);
    }
    const Ctor = DTYPES[c.dtype] || Uint8Array;
    if (c.kind === "array") {
      const data = view(buf, base, spans, c.buffer, Ctor);
      return Array.from({ length: count }, (_, k) => data.subarray(k * c.size, (k + 1) * c.size));
    }
    if (c.kind === "ragged") {
      const data = view(buf, base, spans, c.buffer, Ctor);
      const at = view(buf, base, spans, c.offsets, Uint32Array);
      return Array.from({ length: count }, (_, k) => data.subarray(at[k], at[k + 1]));
    }
    // "quant": int32 of 1/scale, a frame's change from the one before where "delta" says so
    const ints = view(buf, base, spans, c.buffer, Int32Array);
    const at = view(buf, base, spans, c.offsets, Uint32Array);
    const delta = view(buf, base, spans, c.delta, Uint8Array);
    const out = [];
    let sum = null;
    for (let k = 0; k < count; k++) {
      const part = ints.subarray(at[k], at[k + 1]);
      if (!delta[k] || sum === null) sum = Float64Array.from(part);
      else for (let i = 0; i < part.length; i++) sum[i] += part[i];
      const value = new Ctor(part.length);
      for (let i = 0; i < part.length; i++) value[i] = sum[i] / c.scale;
      out.push(value);
    }
    return out;
  }
  async function decode(bytes) {
    const buf = await inflate(bytes);
    const n = new DataView(buf).getUint32(0, true);
    const head = JSON.parse(new TextDecoder().decode(new Uint8Array(buf, 4, n)));
    const base = 4 + n + ((8 - ((4 + n) % 8)) % 8);
    const spans = head.buffers;
    const block = {
      nodeset: head.nodeset, first: head.first, count: head.count, total: head.total, times: head.times,
      nodes: head.nodes, prologue: head.prologue.map((m) => arrays(m, buf, base, spans)), consts: [], columns: [],
    };
    for (const c of head.columns) {
      if (c.kind === "const") block.consts.push({ key: c.key, value: arrays(c.value, buf, base, spans) });
      else block.columns.push({
        key: c.key, values: columnValues(c, head.count, buf, base, spans),
        changed: view(buf, base, spans, c.changed, Uint8Array),
      });
    }
    return block;
  }
  // pieces of node state (a column's key) as the scene messages that set them, one per node
  function messages(pieces, owner) {
    const updates = new Map();
    const out = [];
    for (const [key, value] of pieces) {
      const [what, name, prop] = key;
      if (what === "props") {
        let m = updates.get(name);
        if (!m) { m = { type: "SceneNodeUpdateMessage", name, updates: {}, owner }; updates.set(name, m); out.push(m); }
        m.updates[prop] = value;
      } else if (what === "position") out.push({ type: "SetPositionMessage", name, position: value, owner });
      else if (what === "wxyz") out.push({ type: "SetOrientationMessage", name, wxyz: value, owner });
      else if (what === "visible") out.push({ type: "SetSceneNodeVisibilityMessage", name, visible: value, owner });
    }
    return out;
  }

  // ------------------------------------------------------------------ the runtime
  // The lecturer's lead token (rigidrel serve --follow prints the address with ?lead=...): kept
  // for this tab's reloads, and taken out of the address bar, which a projector shows.
  function leadToken() {
    const params = new URLSearchParams(location.search);
    let lead = params.get("lead");
    try {
      if (lead) sessionStorage.setItem("rigidrel-lead", lead);
      else lead = sessionStorage.getItem("rigidrel-lead");
    } catch (e) { /* storage refused: the address's token still counts */ }
    if (params.has("lead")) {
      params.delete("lead");
      const rest = params.toString();
      history.replaceState(history.state, "", location.pathname + (rest ? "?" + rest : "") + location.hash);
    }
    return lead;
  }

  class Runtime {
    constructor() {
      this.viewer = null;
      this.push = null;
      this.queue = null;
      this.disposed = false;
      this.deadline = performance.now() + 15000;
      this.timelines = new Map(); // id -> {first block's nodes/prologue/consts, blocks: Map first -> block, total, times}
      this.pending = Promise.resolve(); // payloads decode in the order they came
      this.nodeset = null; // the node set the moving parts are drawn on now
      this.page = null; // the shared still picture shown (its node set), or null
      this.created = new Set(); // the moving nodes this runtime made
      this.current = null; // the timeline playing or shown (its id), or null: the server's own frame
      this.applied = -1; // its frame on screen
      this.playing = false;
      this.speed = 1;
      this.loop = true;
      this.anchorFrame = 0;
      this.anchorTime = 0;
      this.position = 0;
      this.waiting = false;
      this.raf = null;
      this.clockAt = 0;
      this.stats = { frames: 0, messages: 0, waits: 0, blocks: 0 };
      this.unwatch = []; // the pointer's listeners, removed when a new runtime replaces this one
      this.install();
    }
    install() {
      if (this.disposed) return;
      const viewer = findViewer();
      if (!viewer) {
        if (performance.now() < this.deadline) requestAnimationFrame(() => this.install());
        else console.error("rigidrel: viser's viewer not found; the server draws this tab's frames");
        return;
      }
      this.viewer = viewer;
      const queue = viewer.mutable.current.messageQueue;
      const push = queue.push.bind(queue);
      queue.push = (...items) => {
        const rest = items.filter((m) => !this.take(m));
        return rest.length ? push(...rest) : queue.length;
      };
      this.queue = queue;
      this.push = push;
      this.lockCamera(viewer);
      this.watchPointer();
      const lead = leadToken();
      const ready = { event: "ready" };
      if (lead) ready.lead = lead;
      // a browser asking for reduced motion: no lesson step starts playing by itself
      if (win.matchMedia && win.matchMedia("(prefers-reduced-motion: reduce)").matches) ready.still = true;
      this.report(ready);
    }
    // The page is a flat picture the server keeps in view: a drag, the wheel, a touch or the arrow
    // keys must not orbit, zoom or tilt it mid-lecture (the arrows step time, the server's keys).
    // viser's own lock (the one its gizmo drags take) disables its camera controls, keyboard
    // movement included; the server still sets the camera. The crosshair those keys would show goes.
    lockCamera(viewer) {
      const locks = viewer.interaction && viewer.interaction.cameraLocks;
      if (!locks || typeof locks.acquire !== "function") {
        console.error("rigidrel: viser's camera lock not found; the mouse can move the picture");
        return;
      }
      this.releaseCamera = locks.acquire("rigidrel: the picture stays in view");
      const dev = viewer.useDevSettings;
      if (dev && typeof dev.setState === "function") dev.setState({ enableOrbitCrosshair: false });
    }
    // The pointer does physics (rigidrel_app/view/pointer.py): a press, a drag (reported at most
    // every POINTER_MS) and a release on the canvas go to the server in the canvas' CSS px, from its
    // top left corner. A touch is a pointer too; the page does not scroll or zoom under it.
    watchPointer() {
      const canvas = document.querySelector("canvas[data-engine]");
      if (!canvas) {
        if (!this.disposed && performance.now() < this.deadline) requestAnimationFrame(() => this.watchPointer());
        return;
      }
      canvas.style.touchAction = "none";
      let down = null; // the pointer pressed, if any
      let pending = null;
      let timer = null;
      let last = 0;
      const at = (e) => {
        const r = canvas.getBoundingClientRect();
        return { x: e.clientX - r.left, y: e.clientY - r.top };
      };
      // each report carries the latest events, numbered: the server takes those it has not seen
      // (it reads the report box's newest value, which a later report may already have replaced)
      const run = Math.random().toString(36).slice(2, 12);
      const log = [];
      let seq = 0;
      const send = (phase, where) => {
        log.push({ seq: ++seq, phase, x: where.x, y: where.y });
        if (log.length > POINTER_EVENTS) log.shift();
        this.report({ event: "pointer", run, events: log });
      };
      const flush = () => {
        timer = null;
        if (!pending) return;
        send("move", pending);
        pending = null;
        last = performance.now();
      };
      const on = (type, handler) => {
        canvas.addEventListener(type, handler);
        this.unwatch.push(() => canvas.removeEventListener(type, handler));
      };
      on("pointerdown", (e) => {
        if (e.button !== 0 || down !== null) return;
        down = e.pointerId;
        canvas.setPointerCapture(e.pointerId);
        send("down", at(e));
        last = performance.now();
      });
      on("pointermove", (e) => {
        if (e.pointerId !== down) return;
        pending = at(e);
        const wait = POINTER_MS - (performance.now() - last);
        if (wait <= 0) flush();
        else if (timer === null) timer = setTimeout(flush, wait);
      });
      const up = (e) => {
        if (e.pointerId !== down) return;
        down = null;
        if (timer !== null) clearTimeout(timer);
        flush();
        send("up", at(e));
      };
      on("pointerup", up);
      on("pointercancel", up);
    }
    cameraLocked() {
      const control = this.viewer && this.viewer.mutable.current.cameraControl;
      return !!control && control.enabled === false;
    }
    dispose() {
      this.disposed = true;
      if (this.releaseCamera) this.releaseCamera();
      for (const undo of this.unwatch) undo();
      if (this.raf !== null) cancelAnimationFrame(this.raf);
      if (this.queue && this.push) this.queue.push = this.push;
    }
    report(what) {
      const text = JSON.stringify(what);
      this.viewer.mutable.current.sendMessage({ type: "GuiUpdateMessage", uuid: CONFIG.report, updates: { value: text } });
    }
    send(out) {
      if (!out.length) return;
      for (const m of out) this.push(m);
      this.stats.messages += out.length;
      this.viewer.mutable.current.requestRender();
    }
    take(m) {
      if (m.type !== "PlaybackMessage") return false;
      // decoding is asynchronous (gzip): every action waits for the payloads before it
      this.pending = this.pending.then(async () => {
        const block = m.payload && m.payload.length ? await decode(m.payload) : null;
        this.act(m.action, m.timeline, m.value, block);
      }).catch((e) => console.error("rigidrel playback:", e));
      return true;
    }
    act(action, id, value, block) {
      if (action === "frame") { // the server's own frame (an answer, a seek): shown now, playing stops
        this.stop();
        this.current = null;
        this.show(block);
      } else if (action === "block") {
        let t = this.timelines.get(id);
        if (!t) { t = { blocks: new Map(), total: block.total, head: null }; this.timelines.set(id, t); }
        if (block.first === 0) t.head = block;
        t.blocks.set(block.first, block);
        this.stats.blocks += 1;
        if (this.waiting && this.current === id && this.blockOf(this.position)) this.resume();
      } else if (action === "page") { // a still picture shared with other tabs (value 1), or its end (0)
        this.showPage(value ? block : null);
      } else if (action === "forget") {
        this.timelines.delete(id);
      } else if (action === "speed") {
        const f = this.frameNow();
        this.speed = value;
        this.anchor(f);
      } else if (action === "loop") {
        this.loop = value !== 0;
      } else if (action === "play") {
        this.current = id;
        this.anchor(value);
        this.playing = true;
        this.waiting = false;
        this.schedule();
      } else if (action === "seek") {
        this.stop();
        this.current = id;
        this.position = value;
        this.showFrame(Math.round(value), false);
      } else if (action === "pause") {
        if (this.current === id && this.total()) { // playing, or holding for a block: where it is
          const k = Math.max(0, Math.min(this.total() - 1, Math.round(this.frameNow())));
          this.stop();
          this.position = k;
          if (this.blockOf(k)) this.showFrame(k, false);
          this.report({ event: "paused", timeline: id, frame: this.blockOf(k) ? k : Math.max(0, this.applied) });
        }
      } else if (action === "stop") {
        this.stop();
      }
    }
    stop() {
      this.playing = false;
      this.waiting = false;
      if (this.raf !== null) { cancelAnimationFrame(this.raf); this.raf = null; }
    }
    timeline() { return this.current === null ? null : this.timelines.get(this.current); }
    total() { const t = this.timeline(); return t ? t.total : 0; }
    blockOf(k) {
      const t = this.timeline();
      if (!t || !t.head) return null;
      const size = t.head.count;
      return t.blocks.get(Math.floor(k / size) * size) || null;
    }
    anchor(f) { this.anchorFrame = f; this.anchorTime = performance.now(); this.position = f; }
    frameNow() {
      return this.playing ? this.anchorFrame + ((performance.now() - this.anchorTime) / 1000) * FRAME_RATE * this.speed : this.position;
    }
    resume() { this.waiting = false; this.anchor(this.position); this.playing = true; this.schedule(); }
    schedule() {
      if (this.raf === null && !this.disposed) this.raf = requestAnimationFrame(() => this.tick());
    }
    tick() {
      this.raf = null;
      if (!this.playing) return;
      const total = this.total();
      if (!total) { this.waiting = true; this.position = this.anchorFrame; return; }
      let f = this.frameNow();
      const last = total - 1;
      if (f >= last) {
        if (this.loop && last > 0) { f %= last; this.anchor(f); }
        else {
          this.stop();
          this.position = last;
          this.showFrame(last, true);
          this.report({ event: "ended", timeline: this.current, frame: last });
          return;
        }
      }
      const k = Math.floor(f);
      if (!this.blockOf(k)) { // its block is on its way: hold the picture until it comes
        this.stats.waits += 1;
        this.playing = false;
        this.waiting = true;
        this.position = k;
        return;
      }
      if (k !== this.applied) this.showFrame(k, true);
      this.schedule();
    }
    // frame k of the current timeline; `onward`: the frame after the one on screen may send only what changed
    showFrame(k, onward) {
      const block = this.blockOf(k);
      if (!block) return;
      const t = this.timeline();
      const sameSet = this.nodeset === t.head.nodeset;
      if (!sameSet) this.switchTo(t.head);
      const i = k - block.first;
      const step = onward && sameSet && this.applied >= 0 && k === this.applied + 1 && i > 0;
      const pieces = [];
      for (const c of block.columns) if (!step || c.changed[i]) pieces.push([c.key, c.values[i]]);
      if (!step) for (const c of block.consts) pieces.push([c.key, c.value]); // what this block holds still
      this.send(messages(pieces, CONFIG.owner));
      this.applied = k;
      this.stats.frames += 1;
      this.clock(block.times[i]);
    }
    // the server's one frame (a block of one), shown whole
    show(block) {
      if (this.nodeset !== block.nodeset || block.prologue.length) this.switchTo(block);
      else this.send(messages(block.consts.map((c) => [c.key, c.value]), CONFIG.owner));
      this.applied = -1;
      this.stats.frames += 1;
    }
    // the shared still picture: the old one removed whole (one node), the new one made under it
    showPage(block) {
      const out = [];
      if (this.page !== null) out.push({ type: "RemoveSceneNodeMessage", name: CONFIG.sharedRoot, owner: CONFIG.owner });
      this.page = null;
      if (block) {
        for (const m of block.prologue) out.push(Object.assign({}, m, { owner: CONFIG.owner }));
        this.page = block.nodeset;
      }
      this.send(out);
      if (block) this.send(messages(block.consts.map((c) => [c.key, c.value]), CONFIG.owner));
    }
    // draw on another node set: make its nodes, hide ours it does not have, set what never changes
    switchTo(head) {
      const out = [];
      for (const m of head.prologue) out.push(Object.assign({}, m, { owner: CONFIG.owner }));
      const nodes = new Set(head.nodes);
      for (const name of this.created) {
        if (!nodes.has(name)) out.push({ type: "SetSceneNodeVisibilityMessage", name, visible: false, owner: CONFIG.owner });
      }
      for (const name of nodes) this.created.add(name);
      this.send(out);
      this.send(messages(head.consts.map((c) => [c.key, c.value]), CONFIG.owner));
      this.nodeset = head.nodeset;
    }
    // what viser's client holds of a scene node (for the browser tests): its props and visibility
    node(name) {
      const node = this.viewer && this.viewer.useSceneTree.get(name);
      if (!node) return null;
      const props = {};
      for (const [k, v] of Object.entries(node.message.props || {})) props[k] = ArrayBuffer.isView(v) ? Array.from(v) : v;
      return { props, visible: node.visibility !== false };
    }
    // the time controls, at CLOCK_HZ while playing and on every still frame
    clock(time) {
      const now = performance.now();
      if (this.playing && now - this.clockAt < 1000 / CLOCK_HZ) return;
      this.clockAt = now;
      const value = Math.round(time * 1e6) / 1e6;
      const shown = String(Number(value.toPrecision(6)));
      this.send(CONFIG.clock.map(([uuid, kind]) => ({
        type: "GuiUpdateMessage", uuid, updates: { value: kind === "text" ? shown : value },
      })));
    }
  }
  win.__rigidrelPlayback = new Runtime();
})();
