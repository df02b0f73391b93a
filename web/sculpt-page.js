// SPDX-License-Identifier: GPL-3.0-or-later
// The page around the viewer (sculpt-view.wasm, the same program as the desktop's): its command
// line from the page's address, its reconstructions in Web Workers, the files a user picks or
// drops, the downloads it hands back, and what the browser tests ask of it (window.sculpt).

const status = document.getElementById('status');
const canvas = document.getElementById('canvas');

function show(message, isError = false) {
  status.textContent = message;
  status.classList.toggle('error', isError);
  status.hidden = false;
}

// The address's parameters as the viewer's options: ?example=torus&method=paper&stage=poles,
// ?figure=fig06&panel=c, ?lesson=undersampling, ?present=on&scale=2 (a class). Unknown ones are refused by the viewer in one
// line, as on the command line.
const options = {
  example: '--example', method: '--method', stage: '--stage', step: '--step',
  sample: '--pick-sample', figure: '--figure', panel: '--panel', lesson: '--lesson',
  text: '--font-scale', scale: '--picture-scale', palette: '--palette',
};
// A refusal of the command line in the address's words: `stage` for `--stage`, and no pointer
// to a --help the page cannot show.
function inAddressWords(line) {
  let words = line.replace(/^sculpt-view: usage error: /, 'This link cannot be opened: ')
    .replace(/ \(see sculpt-view --help\)$/, '');
  for (const [key, option] of Object.entries(options)) {
    words = words.replaceAll(new RegExp(`${option}\\b`, 'g'), key);
  }
  return words;
}

function argumentsFromAddress() {
  const args = [];
  for (const [key, value] of new URLSearchParams(location.search)) {
    if (key in options) {
      args.push(options[key], value);
    } else if (key === 'kind' && (value === 'closed' || value === 'bordered')) {
      args.push(`--${value}`);
    } else if (key === 'present' && value === 'on') {
      args.push('--present');
    } else if (key === 'animation' && value === 'off') {
      args.push('--no-animation');
    } else {
      args.push(`--${key}`, value);  // the viewer names what it does not know
    }
  }
  const density = window.devicePixelRatio || 1;
  const width = Math.max(320, Math.round(canvas.clientWidth * density));
  const height = Math.max(240, Math.round(canvas.clientHeight * density));
  args.push('--size', `${width}x${height}`);
  if (density > 1.25 && !new URLSearchParams(location.search).has('text')) {
    args.push('--font-scale', String(Math.min(4, density)));
  }
  return args;
}

// ---------------------------------------------------------------------------------------------
// Reconstructions in Web Workers (src/viewer/platform/worker_job.cpp asks for them), a worker for
// each job running: side by side runs the compared methods beside the main job. The core's
// module is compiled once and handed to each worker; one worker done with its job waits for
// the next, and a cancel ends the job's worker (one more stands ready).

const coreUrl = new URL('sculpt/sculpt-core.wasm', import.meta.url);
const compiledCore = WebAssembly.compileStreaming(fetch(coreUrl)).catch(async () => {
  const response = await fetch(coreUrl);
  if (!response.ok) throw new Error(`${coreUrl} answers ${response.status}`);
  return WebAssembly.compile(await response.arrayBuffer());
});
let coreFailure = '';  // why the core cannot be had, once it is known
compiledCore.catch((error) => {
  coreFailure = `the reconstruction module cannot be loaded (${error.message})`;
  for (const id of [...jobs.running.keys()]) jobs.finish(id, coreFailure, '', null);
});

const jobs = {
  idle: [],             // workers waiting for a job
  running: new Map(),   // a job's id -> its worker (null while its file is read)
  started: 0,           // how many the viewer asked for (the tests wait for a dropped file's)

  // A worker given the compiled core; its messages are heeded while it runs a job.
  spawn() {
    const worker = new Worker(new URL('reconstruction-worker.mjs', import.meta.url),
                              { type: 'module' });
    worker.onmessage = ({ data }) => this.receive(worker, data);
    worker.onerror = (event) => {
      // A worker that failed is not trusted with the next job.
      worker.terminate();
      this.idle = this.idle.filter((w) => w !== worker);
      const failed = this.jobOf(worker);
      if (failed) this.finish(failed, `the reconstruction stopped: ${event.message}`, '', null);
    };
    compiledCore.then((module) => worker.postMessage({ type: 'init', module }), () => {});
    return worker;
  },

  // One worker stands ready, so that a job starts without waiting for the core to start.
  keepOneReady() {
    if (this.idle.length === 0) this.idle.push(this.spawn());
  },

  jobOf(worker) {
    for (const [id, w] of this.running) if (w === worker) return id;
    return 0;
  },

  async start(id, request, path) {
    this.running.set(id, null);
    ++this.started;
    if (coreFailure) {
      this.finish(id, coreFailure, '', null);
      return;
    }
    let bytes = null;
    try {
      bytes = await fileBytes(path);
    } catch (error) {
      if (this.running.has(id)) this.finish(id, error.message, '', null);
      return;
    }
    if (!this.running.has(id)) return;  // cancelled meanwhile
    const worker = this.idle.pop() ?? this.spawn();
    this.running.set(id, worker);
    worker.postMessage({ type: 'run', id, request, path, bytes }, bytes ? [bytes.buffer] : []);
  },

  cancel(id) {
    if (!this.running.has(id)) return;
    const worker = this.running.get(id);
    if (worker) worker.terminate();
    this.finish(id, 'cancelled', '', null);
    this.keepOneReady();
  },

  receive(worker, message) {
    if (this.running.get(message.id) !== worker) return;
    if (message.type === 'progress') {
      withText(message.stage, (stage) =>
        Module._sculpt_job_progress(message.id, stage, message.fraction, message.overall));
    } else if (message.type === 'done') {
      // One worker is kept for the next job, others go with the memory their jobs grew. The kept
      // one holds its heap (a WebAssembly heap never shrinks), at most the largest job's: a
      // fresh worker would free it, but loading one needs the network, and once loaded the page
      // works offline.
      if (this.idle.length === 0) this.idle.push(worker);
      else worker.terminate();
      this.finish(message.id, message.error, message.description,
                  message.bytes ? new Uint8Array(message.bytes) : null);
    }
  },

  // Hands the end of a job to the viewer: its error (a bare message, the viewer says "error: "),
  // or its reconstruction's bytes.
  finish(id, error, description, bytes) {
    this.running.delete(id);
    const memory = bytes ? Module._malloc(bytes.length) : 0;
    if (bytes && !memory) {
      bytes = null;
      error = 'out of memory: the page cannot hold this reconstruction';
    }
    try {
      if (bytes) Module.HEAPU8.set(bytes, memory);
      withText(error, (errorText) => withText(description, (descriptionText) =>
        Module._sculpt_job_finished(id, errorText, descriptionText, memory, bytes ? bytes.length : 0)));
    } finally {
      if (memory) Module._free(memory);
    }
  },
};

function withText(text, use) {
  const pointer = Module.allocateUTF8(String(text ?? ''));
  try {
    return use(pointer);
  } finally {
    Module._free(pointer);
  }
}

// The bytes a request reads: a file the user gave (in the viewer's file system), or one of the
// CGAL meshes the paper's figures are drawn from (fetched from the site once, then kept).
async function fileBytes(path) {
  if (!path) return null;
  if (Module.FS.analyzePath(path).exists) return Module.FS.readFile(path);
  const mesh = path.match(/^\/cgal\/([\w.-]+)$/);
  if (!mesh) return null;  // the worker says the file cannot be opened, as the command line does
  const response = await fetch(new URL(`meshes/${mesh[1]}`, import.meta.url));
  if (!response.ok) throw new Error(`cannot fetch the mesh ${mesh[1]} (${response.status})`);
  const bytes = new Uint8Array(await response.arrayBuffer());
  Module.FS.mkdirTree('/cgal');
  Module.FS.writeFile(path, bytes);
  return bytes.slice();
}

async function prefetchMeshes() {
  const names = await (await fetch(new URL('meshes/list.json', import.meta.url))).json();
  for (const name of names) {
    if (!Module.FS.analyzePath(`/cgal/${name}`).exists) await fileBytes(`/cgal/${name}`);
  }
  window.sculpt.meshesLoaded = true;
}

// ---------------------------------------------------------------------------------------------
// Files in and out (src/viewer/platform/web.cpp).

const page = {
  // A file the viewer wrote, handed to the user as a download.
  download(name, bytes) {
    const url = URL.createObjectURL(new Blob([bytes]));
    const link = document.createElement('a');
    link.href = url;
    link.download = name;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 60000);
    window.sculpt.downloads.push(name);
  },

  // The browser's file picker: the file is written into the viewer's file system and opened.
  chooseFile() {
    const input = document.createElement('input');
    input.type = 'file';
    input.accept = '.xyz,.pts,.txt,.csv,.pwn,.xy,.p2d,.ply,.off,.obj,.stl,.las,.pcd';
    input.addEventListener('change', async () => {
      const file = input.files[0];
      if (file) await openFile(file);
    });
    input.click();
  },

  copyText(text) {
    navigator.clipboard?.writeText(text).catch(() => {});
    window.sculpt.copied = text;
  },

  // The viewer's main loop has started: its first frame is next.
  started() {
    window.sculpt.started = true;
    status.hidden = true;
    canvas.focus();  // the keys (arrows, Page Down, E, ...) work before any click
    // Then, while the page is idle, the figures' meshes: once loaded, the tour needs no network.
    setTimeout(() => prefetchMeshes().catch(() => {}), 2000);
  },
};

async function openFile(file) {
  const path = `/files/${file.name.replace(/[/\\]/g, '_')}`;
  Module.FS.mkdirTree('/files');
  Module.FS.writeFile(path, new Uint8Array(await file.arrayBuffer()));
  withText(path, (pathText) => Module._sculpt_open_file(pathText));
}

// ---------------------------------------------------------------------------------------------
// Touch: one finger is the mouse's left button (a tap adds a sample while editing, a drag
// orbits or pans), two fingers pinching are the wheel (zoom). Emscripten's GLFW reads no touch
// positions (only SDL's events carry them), so touches reach it as the mouse events they mean,
// registered before its own listeners and in their place.

function touchAsMouse(target) {
  let pinch = null;  // the fingers' last distance while two are down
  const mouse = (type, touch, buttons) => target.dispatchEvent(new MouseEvent(type, {
    clientX: touch.clientX, clientY: touch.clientY, button: 0, buttons, bubbles: true, cancelable: true,
  }));
  const distance = (touches) => Math.hypot(touches[0].clientX - touches[1].clientX,
                                           touches[0].clientY - touches[1].clientY);
  const take = (event) => {
    event.preventDefault();  // no scrolling, no page zoom, no mouse events made up by the browser
    event.stopImmediatePropagation();
  };
  target.addEventListener('touchstart', (event) => {
    take(event);
    if (event.touches.length === 1) {
      mouse('mousemove', event.touches[0], 0);
      mouse('mousedown', event.touches[0], 1);
    } else if (event.touches.length === 2) {
      mouse('mouseup', event.touches[0], 0);  // a pinch is not a drag
      pinch = distance(event.touches);
    }
  }, { capture: true, passive: false });
  target.addEventListener('touchmove', (event) => {
    take(event);
    if (event.touches.length === 1 && pinch === null) {
      mouse('mousemove', event.touches[0], 1);
    } else if (event.touches.length === 2 && pinch !== null) {
      const now = distance(event.touches);
      target.dispatchEvent(new WheelEvent('wheel', {
        clientX: (event.touches[0].clientX + event.touches[1].clientX) / 2,
        clientY: (event.touches[0].clientY + event.touches[1].clientY) / 2,
        deltaY: (pinch - now) * 2, bubbles: true, cancelable: true,
      }));
      pinch = now;
    }
  }, { capture: true, passive: false });
  const end = (event) => {
    take(event);
    if (event.touches.length === 0) {
      if (pinch === null) mouse('mouseup', event.changedTouches[0], 0);
      pinch = null;
    }
  };
  target.addEventListener('touchend', end, { capture: true, passive: false });
  target.addEventListener('touchcancel', end, { capture: true, passive: false });
}

// ---------------------------------------------------------------------------------------------
// What tests and scripts may ask of the page.

window.sculpt = {
  downloads: [],
  copied: '',
  errors: [],
  // Runs viewer script commands (src/viewer/script.hpp) and resolves when they have run: true if
  // every command succeeded.
  async run(script) {
    // After the script running (the first view a link asks for), not instead of it.
    while (Module._sculpt_script_state() === 1) await new Promise((resolve) => setTimeout(resolve, 20));
    withText(script, (text) => Module._sculpt_run_script(text));
    for (;;) {
      // 2 succeeded, 3 failed, 4 a lesson waiting at a picture (its Next is the user's).
      const state = Module._sculpt_script_state();
      if (state === 2 || state === 3 || state === 4) return state !== 3;
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
  },
  openFile,
};

// ---------------------------------------------------------------------------------------------
// Start.

if (!document.createElement('canvas').getContext('webgl2')) {
  show('Sculpt needs WebGL 2, which this browser does not give the page.\n' +
       'Try a current Firefox, Chrome, Edge or Safari, or turn on hardware acceleration.', true);
} else if (typeof WebAssembly !== 'object') {
  show('Sculpt needs WebAssembly, which this browser does not offer.', true);
} else {
  canvas.addEventListener('contextmenu', (event) => event.preventDefault());
  touchAsMouse(canvas);
  jobs.keepOneReady();
  window.Module = {
    canvas,
    arguments: argumentsFromAddress(),
    sculptJobs: jobs,
    sculptPage: page,
    print: (line) => console.log(line),
    printErr: (line) => {
      // The viewer's refusals (a link's unknown option, a script's bad command) are one line
      // each: shown on the page as well as in the console.
      console.warn(line);
      window.sculpt.errors.push(line);
      if (!window.sculpt.started) show(inAddressWords(line), true);
    },
  };
  window.sculpt.firstFrame = new Promise((resolve) => {
    const wait = () => (canvas.width > 0 && window.sculpt.started ? resolve(performance.now())
                                                                  : requestAnimationFrame(wait));
    requestAnimationFrame(wait);
  });
  const script = document.createElement('script');
  script.src = 'sculpt-view.js';
  script.onerror = () => show('Sculpt could not be loaded from this address.', true);
  document.body.appendChild(script);
}
