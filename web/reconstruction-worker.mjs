// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer's reconstructions, off the page's thread: a request (frontend::Reconstruction_request
// as JSON) and its input file's bytes in; progress, then the reconstruction with every stage as
// bytes out (src/web/core_module.cpp, sculpt_run_request). The page hands in the compiled core.
import createSculptCore from './sculpt/sculpt-core.mjs';

let core = null;
const waiting = [];

let failure = '';  // why the core could not be started, if it could not

onmessage = async ({ data }) => {
  if (data.type === 'init') {
    try {
      core = await createSculptCore({
        instantiateWasm(imports, receive) {
          WebAssembly.instantiate(data.module, imports)
            .then((instance) => receive(instance, data.module))
            .catch((error) => fail(`the reconstruction module does not start: ${error.message}`));
          return {};
        },
        print: (line) => console.log(line),
        printErr: (line) => console.warn(line),
      });
    } catch (error) {
      fail(`the reconstruction module does not start: ${error.message}`);
      return;
    }
    while (waiting.length) attempt(waiting.shift());
  } else if (data.type === 'run') {
    if (failure) postMessage({ type: 'done', id: data.id, error: failure });
    else if (core) attempt(data);
    else waiting.push(data);
  }
};

function fail(why) {
  failure = why;
  while (waiting.length) postMessage({ type: 'done', id: waiting.shift().id, error: failure });
}

// A run always answers: with its result, or with why it has none.
function attempt(job) {
  try {
    run(job);
  } catch (error) {
    postMessage({ type: 'done', id: job.id, error: `the reconstruction stopped: ${error.message ?? error}` });
  }
}

function run({ id, request, path, bytes }) {
  // The file is read by its name alone, in a folder of its own: the description and any refusal
  // name it as the user knows it ("scan.ply"), not by where the page keeps it.
  let name = '';
  if (bytes) {
    name = path.substring(path.lastIndexOf('/') + 1);
    core.FS.mkdirTree('/input');
    core.FS.chdir('/input');
    core.FS.writeFile(name, bytes);
    const asked = JSON.parse(request);
    asked.path = name;
    request = JSON.stringify(asked);
  }
  // Progress at most every 50 ms, and at each new stage: the page draws at its own pace.
  let lastStage = '';
  let lastTime = 0;
  core.onProgress = (stage, fraction, overall) => {
    const now = performance.now();
    if (stage !== lastStage || now - lastTime > 50) {
      postMessage({ type: 'progress', id, stage, fraction, overall });
      lastStage = stage;
      lastTime = now;
    }
    return true;
  };
  const text = core.allocateUTF8(request);
  const result = core._sculpt_run_request(text);
  core._free(text);
  const error = core.UTF8ToString(core._sculpt_result_error(result));
  let description = '';
  let out = null;
  if (!error) {
    description = JSON.parse(core.UTF8ToString(core._sculpt_result_json(result))).description;
    const at = core._sculpt_result_bytes(result);
    out = core.HEAPU8.slice(at, at + core._sculpt_result_byte_count(result)).buffer;
  }
  core._sculpt_result_free(result);
  if (bytes) core.FS.unlink(name);
  postMessage({ type: 'done', id, error, description, bytes: out }, out ? [out] : []);
}
