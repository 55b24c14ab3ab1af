// Loads a skybake web export (`skybake export BAKE --format web -o DIR`;
// data_formats/FORMAT.md, "Web export") into WebGL2, for the GLSL library
// (runtime/glsl/README.md) to read. An ES module without dependencies:
//
//   import { loadSkybake, skybakeFragmentSource, bindSkybakeGroup } from './skybake_web.js';
//   const bake = await loadSkybake(gl, 'earth_web/');
//   const program = yourProgram(vertexSource, skybakeFragmentSource(bake, yourMain));
//   bindSkybakeGroup(gl, program, bake.groups[0]);  // tables on units 0 to 6, block on binding 0
//
// A bake of more than 4 channels (a spectral bake) has one group per 4 of
// them: draw once per group, as `skybake render --backend gl` does.

// The tables as WebGL2 textures: 2D tables RGBA32F, 4D tables (3D
// textures of their atlas) RGB16F or RGBA16F; read with texelFetch only.
// Allocated (immutable, at their final size and format) before their bytes
// arrive, so that a program can be compiled and drawn while they download.
function allocateTexture(gl, entry) {
  const target = gl[entry.target];
  const texture = gl.createTexture();
  gl.bindTexture(target, texture);
  // texelFetch ignores filtering, but a float texture whose filter needs
  // mipmaps or linear filtering it lacks is incomplete and reads as 0.
  gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  const [w, h, d] = entry.size;
  if (entry.target === 'TEXTURE_2D') gl.texStorage2D(target, 1, gl[entry.internal_format], w, h);
  else gl.texStorage3D(target, 1, gl[entry.internal_format], w, h, d);
  return texture;
}

function fillTexture(gl, entry, texture, bytes) {
  const target = gl[entry.target];
  gl.bindTexture(target, texture);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);  // rows of 6-byte texels
  const data = entry.type === 'FLOAT' ? new Float32Array(bytes) : new Uint16Array(bytes);
  const [w, h, d] = entry.size;
  if (entry.target === 'TEXTURE_2D') {
    gl.texSubImage2D(target, 0, 0, 0, w, h, gl[entry.format], gl[entry.type], data);
  } else {
    gl.texSubImage3D(target, 0, 0, 0, 0, w, h, d, gl[entry.format], gl[entry.type], data);
  }
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 4);
}

// The uniform block's std140 bytes from the manifest's members: each a
// vec4 or ivec4 (or an array of them), 16 bytes apiece, in order.
function uniformBlockBytes(block) {
  const bytes = new ArrayBuffer(block.bytes);
  let offset = 0;
  for (const member of block.members) {
    const View = member.type === 'ivec4' ? Int32Array : Float32Array;
    new View(bytes, offset, 4 * member.count).set(member.values);
    offset += 16 * member.count;
  }
  if (offset !== block.bytes) throw new Error(`uniform block: members fill ${offset} of ${block.bytes} bytes`);
  return bytes;
}

async function fetchChecked(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response;
}

// A table file's bytes, gunzipped as they arrive where the manifest says
// its encoding is gzip (rather than none).
async function fetchTable(url, entry) {
  if (entry.encoding !== 'gzip' && entry.encoding !== 'none') throw new Error(`${url}: unknown encoding ${entry.encoding}`);
  const response = await fetchChecked(url);
  const body = entry.encoding === 'gzip' ? response.body.pipeThrough(new DecompressionStream('gzip')) : response.body;
  const bytes = await new Response(body).arrayBuffer();
  if (bytes.byteLength !== entry.bytes) throw new Error(`${url}: ${bytes.byteLength} bytes, the manifest says ${entry.bytes}`);
  return bytes;
}

// Loads the export at `base` (a URL ending in '/'): its manifest, the GLSL
// library's text and every group's textures and uniform buffer. Resolves to
// { manifest, glsl, groups: [{ manifest, textures: [{ sampler, target,
// texture }], uniformBuffer }] }. Options: `onProgress(loadedFiles,
// allFiles)` follows the downloads; `onAllocated(bake)` is called with the
// same object once the GLSL is in and the textures exist at their sizes and
// formats but before their bytes do: a caller may compile its programs and
// draw with them then (drivers that build a program at its first draw,
// Mesa's llvmpipe among them, do so while the tables download); its
// pixels mean nothing until the promise resolves.
export async function loadSkybake(gl, base, { onProgress = () => {}, onAllocated = () => {} } = {}) {
  const manifest = await (await fetchChecked(base + 'manifest.json')).json();
  if (manifest.format !== 'skybake-web' || manifest.version !== 1) {
    throw new Error(`${base}manifest.json: not a skybake web export of version 1`);
  }
  const entries = manifest.groups.flatMap((g) => g.textures);
  let loaded = 0;
  const progress = () => onProgress(++loaded, entries.length + 1);
  const glslText = fetchChecked(base + manifest.glsl.file).then((r) => r.text()).then((t) => (progress(), t));
  const groups = manifest.groups.map((group) => {
    const textures = group.textures.map((entry) => ({
      sampler: entry.sampler,
      target: gl[entry.target],
      texture: allocateTexture(gl, entry),
    }));
    const uniformBuffer = gl.createBuffer();
    gl.bindBuffer(gl.UNIFORM_BUFFER, uniformBuffer);
    gl.bufferData(gl.UNIFORM_BUFFER, uniformBlockBytes(group.uniform_block), gl.STATIC_DRAW);
    gl.bindBuffer(gl.UNIFORM_BUFFER, null);
    return { manifest: group, textures, uniformBuffer };
  });
  const tables = Promise.all(entries.map((entry) => fetchTable(base + entry.file, entry).then((b) => (progress(), b))));
  tables.catch(() => {});  // awaited below; a failure before then is not an unhandled one
  const bake = { manifest, glsl: await glslText, groups };
  onAllocated(bake);
  // The tables filled once all are in: a fill waits for the driver's work
  // before it (a program being built), and the downloads, unpacked on this
  // thread, would wait with it.
  const bytes = await tables;
  const textures = groups.flatMap((g) => g.textures);
  entries.forEach((entry, i) => fillTexture(gl, entry, textures[i].texture, bytes[i]));
  return bake;
}

// A fragment shader's source: the ES header and precisions, `defines`, the
// GLSL library, then `main` (the caller's code).
export function skybakeFragmentSource(bake, main, defines = '') {
  return bake.manifest.glsl.es_header + defines + bake.glsl + main;
}

// Makes `program` current and binds one group's tables to texture units
// firstUnit .. firstUnit + 6 and its uniform block to `blockBinding`.
export function bindSkybakeGroup(gl, program, group, firstUnit = 0, blockBinding = 0) {
  gl.useProgram(program);
  const block = gl.getUniformBlockIndex(program, group.manifest.uniform_block.name);
  if (block !== gl.INVALID_INDEX) gl.uniformBlockBinding(program, block, blockBinding);
  gl.bindBufferBase(gl.UNIFORM_BUFFER, blockBinding, group.uniformBuffer);
  group.textures.forEach((t, i) => {
    gl.activeTexture(gl.TEXTURE0 + firstUnit + i);
    gl.bindTexture(t.target, t.texture);
    const location = gl.getUniformLocation(program, t.sampler);
    if (location !== null) gl.uniform1i(location, firstUnit + i);  // null: the shader does not use this table
  });
  gl.activeTexture(gl.TEXTURE0);
}

// Compiles and links a program without waiting for the driver (asking for
// its status would): pass it to checkedProgram before drawing with it.
export function startProgram(gl, vertexSource, fragmentSource) {
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, vertexSource], [gl.FRAGMENT_SHADER, fragmentSource]]) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  return program;
}

// `program` once linked; throws with the compiler's log where it failed.
export function checkedProgram(gl, program) {
  if (gl.getProgramParameter(program, gl.LINK_STATUS)) return program;
  for (const shader of gl.getAttachedShaders(program)) {
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`GLSL: ${gl.getShaderInfoLog(shader)}`);
  }
  throw new Error(`GLSL link: ${gl.getProgramInfoLog(program)}`);
}

// Resolves to `program` once linked (checkedProgram), without blocking the
// page while the driver works where the browser offers
// KHR_parallel_shader_compile (asking for a program's status otherwise
// waits for it).
export async function linkedProgram(gl, program) {
  const parallel = gl.getExtension('KHR_parallel_shader_compile');
  if (parallel) {
    while (!gl.getProgramParameter(program, parallel.COMPLETION_STATUS_KHR)) {
      await new Promise((resolve) => setTimeout(resolve, 5));
    }
  }
  return checkedProgram(gl, program);
}

// Compiles and links a program; throws with the compiler's log.
export function compileProgram(gl, vertexSource, fragmentSource) {
  return checkedProgram(gl, startProgram(gl, vertexSource, fragmentSource));
}

// A full-screen triangle from gl_VertexID, no buffers.
export const fullScreenVertexShader = `#version 300 es
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
`;
