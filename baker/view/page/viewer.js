// skybake view's page: the bake's sky drawn by the GLSL library in WebGL2,
// in three passes per frame: sky_pixels.glsl (`skybake render --backend
// gl`'s fragment stage) gives each pixel's radiance, one lane group of the
// bake at a time; a colour pass adds each group's linear sRGB (the
// manifest's preview_linear_srgb, as render converts channels); a display
// pass applies exposure, the tone map and sRGB encoding with the kernel
// skybakeDisplayValue (runtime/kernel/display_encoding.glsl), the formula
// render's PNG uses. While the view changes, frames are drawn at a quarter
// of the resolution; the full one follows when it rests. The programs are
// compiled, and drawn once, while the tables download; a view that needs
// no integral along its rays (daylight) gets a program without it, and
// the other is built in the background after the first full frame.
import {
  loadSkybake, skybakeFragmentSource, bindSkybakeGroup, startProgram, checkedProgram, linkedProgram, fullScreenVertexShader,
} from './skybake_web.js';

const kDegree = Math.PI / 180;
const kMeanLunarDistance_m = 384400e3;  // runtime/physics/moon_occluder.h
const kTopAltitudeLog_m = 8;            // the altitude control reaches 1e8 m
const kPreviewScale = 0.25;             // resolution while the view changes
const kRestMs = 150;                    // after this long without input, the full resolution
const kSunDiskSubsamples = 4;           // per pixel side, near the sun
const kSunGrabAngle = 4 * kDegree;      // a drag starting this close to the sun moves it
const kToneMaps = { none: 0, reinhard: 1, aces: 2 };  // SKYBAKE_TONE_MAP_*
const kProjections = { fisheye: 0, latlong: 1, perspective: 2 };

const state = {
  projection: 'perspective', altitude_m: 0, sun_zenith_deg: 80, sun_azimuth_deg: 0,
  view_azimuth_deg: 0, view_elevation_deg: 10, fov_deg: 90, exposure: 10, tonemap: 'aces',
  sun_disk: true, moon: false, moon_azimuth_deg: 0, moon_elevation_deg: 10, moon_radius_deg: 0.26,
};
const numberKeys = Object.keys(state).filter((k) => typeof state[k] === 'number');
const query = new URLSearchParams(location.search);
for (const [k, v] of query) {
  if (numberKeys.includes(k) && Number.isFinite(Number(v))) state[k] = Number(v);
  else if (typeof state[k] === 'boolean') state[k] = v === '1' || v === 'true';
  else if (k in state) state[k] = v;
}
// A fixed canvas size (?width=W&height=H), or the window's.
const fixedSize = query.has('width') && query.has('height')
  ? [Math.max(1, parseInt(query.get('width'), 10)), Math.max(1, parseInt(query.get('height'), 10))] : null;

const canvas = document.getElementById('sky');
const statusLine = document.getElementById('status');
const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });

// ---- geometry, as data_formats/angles.h and baker/render/sky_image.cpp ----
const fromZenithAzimuth = (z, a) => [Math.sin(z) * Math.cos(a), Math.sin(z) * Math.sin(a), Math.cos(z)];
const fromElevationAzimuth = (e, a) => [Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e)];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const scale = (a, s) => a.map((x) => x * s);
const add = (...vs) => vs.reduce((s, v) => s.map((x, i) => x + v[i]));
const normalize = (a) => scale(a, 1 / Math.hypot(...a));

function perspectiveFrame(width, height) {
  const forward = fromElevationAzimuth(state.view_elevation_deg * kDegree, state.view_azimuth_deg * kDegree);
  const right = normalize(cross(forward, [0, 0, 1]));
  const up = cross(right, forward);
  const halfWidth = Math.tan(Math.min(state.fov_deg, 179) * kDegree * 0.5);
  return { forward, right, up, halfWidth, halfHeight: halfWidth * height / width };
}

// The view direction through image point (x, y) of a width x height image,
// or null outside the projection (directionAtImagePoint).
function directionAt(x, y, width, height) {
  const u = x / width, w = y / height;
  if (state.projection === 'latlong') {
    return fromZenithAzimuth(w * Math.PI, state.sun_azimuth_deg * kDegree + (u - 0.5) * 2 * Math.PI);
  }
  if (state.projection === 'fisheye') {
    const s = Math.min(width, height);
    const px = (2 * x - width) / s, py = (height - 2 * y) / s;
    const rho = Math.hypot(px, py);
    if (rho > 1) return null;
    return fromZenithAzimuth(rho * state.fov_deg * kDegree * 0.5, state.sun_azimuth_deg * kDegree + Math.atan2(px, py));
  }
  const f = perspectiveFrame(width, height);
  return normalize(add(f.forward, scale(f.right, (2 * u - 1) * f.halfWidth), scale(f.up, (1 - 2 * w) * f.halfHeight)));
}

const sunDirection = () => fromZenithAzimuth(state.sun_zenith_deg * kDegree, state.sun_azimuth_deg * kDegree);

// ---- the passes ----
const colourPassSource = `#version 300 es
precision highp float;
uniform sampler2D radiance;  // one lane group's radiance
uniform sampler2D previous;  // the groups' colour so far
uniform int first_group;
uniform vec3 lane_srgb[4];   // preview linear sRGB per unit of each lane
out vec4 colour;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 v = texelFetch(radiance, p, 0);
  vec3 sum = first_group == 1 ? vec3(0.0) : texelFetch(previous, p, 0).rgb;
  colour = vec4(sum + lane_srgb[0] * v.x + lane_srgb[1] * v.y + lane_srgb[2] * v.z + lane_srgb[3] * v.w, 1.0);
}
`;
const displayMain = `
uniform sampler2D preview_srgb;  // the frame's linear sRGB at render's preview scale
uniform vec2 texels_per_pixel;   // the frame's resolution over the canvas's
uniform float exposure;
uniform int tone_map;            // SKYBAKE_TONE_MAP_*
out vec4 display;
void main() {
  ivec2 size = textureSize(preview_srgb, 0);
  ivec2 p = min(ivec2(gl_FragCoord.xy * texels_per_pixel), size - 1);
  vec3 c = texelFetch(preview_srgb, p, 0).rgb;
  display = vec4(skybakeDisplayValue(c.r, exposure, tone_map), skybakeDisplayValue(c.g, exposure, tone_map),
                 skybakeDisplayValue(c.b, exposure, tone_map), 1.0);
}
`;

function floatTarget(width, height) {
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, width, height);
  const framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) {
    throw new Error('this WebGL2 cannot draw into RGBA32F textures');
  }
  return { texture, framebuffer, width, height };
}

let bake = null;
const programs = { sky: new Map() };  // sky: by their defines, as startProgram gave them
const checkedPrograms = new Set();    // the programs checkedProgram passed
let targets = null;  // radiance, and two colour targets to add groups into

const uniformMember = (name) => bake.groups[0].manifest.uniform_block.members.find((m) => m.name === name).values;

// A constant the GLSL library defines (its skybake_parameters).
function libraryConstant(name) {
  const match = bake.glsl.match(new RegExp(`#define ${name} (\\S+)`));
  if (!match) throw new Error(`the bake's GLSL defines no ${name}`);
  return Number(match[1]);
}

// Whether every ray of the view starts under a sun where the library takes
// single scattering from the tables alone, so that its program may leave
// the integral along the ray out (SKYBAKE_DAYLIGHT_LOOKUPS_ONLY, as
// skybake::gl::daylightLookupsSuffice decides it for render): a camera in
// the atmosphere starts every ray where it is, its sun above the horizon
// and, clamped to the baked suns, at or above
// SKYBAKE_INTEGRATED_SINGLE_SCATTERING_TOP_COSINE.
function daylightView() {
  if (state.moon) return false;
  const [bottom, top] = uniformMember('skybake_radii_m');
  if (bottom + Math.max(state.altitude_m, 0) > top) return false;
  if (!uniformMember('skybake_parts')[0]) return false;  // a bake without ground views: see daylightLookupsSuffice
  const muS = Math.cos(state.sun_zenith_deg * kDegree);
  const [lowest, highest] = uniformMember('skybake_baked_sun_cosines');
  return muS >= 0 && Math.min(Math.max(muS, lowest), highest) >=
    libraryConstant('SKYBAKE_INTEGRATED_SINGLE_SCATTERING_TOP_COSINE');
}

// The sky program of the paths this bake and view take, as render compiles
// them, and the sun disk (which render adds on the CPU): the lit ground
// where the bake has ground irradiance, the table's
// rays to the ground where it holds them, the integral along the ray unless
// the view is lit by day, no lookups of radiance to points, and of
// eclipses only with a moon. Started (compiling) on first use, checked when
// `check`.
function skyProgram(eclipse, daylight, check = true) {
  const defines = '#define SKYBAKE_RENDER_SUN_DISK 1\n' + (eclipse ? '#define SKYBAKE_RENDER_ECLIPSE 1\n' : '') +
    (uniformMember('skybake_outputs')[1] ? '' : '#define SKYBAKE_RENDER_SKY_ONLY 1\n') +
    (uniformMember('skybake_parts')[0] ? '#define SKYBAKE_BAKE_HAS_GROUND_VIEWS 1\n' : '') +
    (daylight ? '#define SKYBAKE_DAYLIGHT_LOOKUPS_ONLY 1\n' : '') + '#define SKYBAKE_NO_RADIANCE_TO_POINT 1\n' +
    (eclipse ? '' : '#define SKYBAKE_NO_ECLIPSE_LOOKUPS 1\n');
  if (!programs.sky.has(defines)) {
    programs.sky.set(defines, startProgram(gl, fullScreenVertexShader, skybakeFragmentSource(bake, skyPixelsSource, defines)));
  }
  const program = programs.sky.get(defines);
  return check ? checked(program) : program;
}

function checked(program) {
  if (!checkedPrograms.has(program)) {
    checkedProgram(gl, program);
    checkedPrograms.add(program);
  }
  return program;
}

function targetsFor(width, height) {
  if (!targets || targets.radiance.width !== width || targets.radiance.height !== height) {
    if (targets) {
      for (const t of [targets.radiance, ...targets.colour]) {
        gl.deleteTexture(t.texture);
        gl.deleteFramebuffer(t.framebuffer);
      }
    }
    targets = { radiance: floatTarget(width, height), colour: [floatTarget(width, height), floatTarget(width, height)] };
  }
  return targets;
}

// The moon at the view's azimuth and elevation from the camera
// (Moon::seenFrom at the mean lunar distance).
function moonOf(camera) {
  const dir = fromElevationAzimuth(state.moon_elevation_deg * kDegree, state.moon_azimuth_deg * kDegree);
  return [...add(camera, scale(dir, kMeanLunarDistance_m)), kMeanLunarDistance_m * Math.sin(state.moon_radius_deg * kDegree)];
}

function setSkyUniforms(program, width, height, group) {
  const u = (name) => gl.getUniformLocation(program, name);
  const block = group.manifest.uniform_block.members;
  const bottom = block.find((m) => m.name === 'skybake_radii_m').values[0];
  const camera = [0, 0, bottom + Math.max(state.altitude_m, 0)];
  const f = perspectiveFrame(width, height);
  gl.uniform2f(u('image_size'), width, height);
  gl.uniform1f(u('strip_top_row'), 0);
  gl.uniform1f(u('strip_rows'), height);
  gl.uniform1i(u('projection'), kProjections[state.projection]);
  gl.uniform1f(u('fov_rad'), state.fov_deg * kDegree);
  gl.uniform1f(u('sun_azimuth_rad'), state.sun_azimuth_deg * kDegree);
  gl.uniform3fv(u('forward'), f.forward);
  gl.uniform3fv(u('right'), f.right);
  gl.uniform3fv(u('up'), f.up);
  gl.uniform2f(u('half_size'), f.halfWidth, f.halfHeight);
  gl.uniform3fv(u('camera_m'), camera);
  gl.uniform3fv(u('sun_dir'), sunDirection());
  gl.uniform1i(u('sun_disk_subsamples'), state.sun_disk ? kSunDiskSubsamples : 0);
  if (state.moon) {
    const top = block.find((m) => m.name === 'skybake_radii_m').values[1];
    gl.uniform4fv(u('moon'), moonOf(camera));
    const inside = Math.hypot(...camera) <= top;
    gl.uniform1i(u('camera_inside'), inside ? 1 : 0);
    gl.uniform1i(u('skylight_pass'), 0);
    const key = JSON.stringify([camera, sunDirection(), moonOf(camera), bake.groups.indexOf(group)]);
    gl.uniform4fv(u('camera_skylight'), inside ? cameraSkylight(program, key) : [1, 1, 1, 1]);
  }
}

// The camera's skylight share under the eclipse: one pixel of the
// skylight pass, as render draws it, into `skylightPixel` (made before the
// tables are bound: making a texture binds it on the active unit).
let skylightPixel = null;
const skylightShares = new Map();  // by camera, sun, moon and group: the same for every frame of one view
function cameraSkylight(program, key) {
  if (skylightShares.has(key)) return skylightShares.get(key);
  if (skylightShares.size > 64) skylightShares.clear();
  gl.bindFramebuffer(gl.FRAMEBUFFER, skylightPixel.framebuffer);
  gl.viewport(0, 0, 1, 1);
  gl.uniform1i(gl.getUniformLocation(program, 'skylight_pass'), 1);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  const share = new Float32Array(4);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, share);
  gl.uniform1i(gl.getUniformLocation(program, 'skylight_pass'), 0);
  skylightShares.set(key, share);
  return share;
}

// Draws one lane group's radiance into `target` (all of it, or the one
// pixel (x, y) from the image's top), with the program `daylight` says.
function drawRadiance(group, target, pixel = null, daylight = daylightView()) {
  const program = skyProgram(state.moon, daylight);
  if (state.moon && !skylightPixel) skylightPixel = floatTarget(1, 1);
  bindSkybakeGroup(gl, program, group);
  setSkyUniforms(program, target.width, target.height, group);  // may draw the skylight pixel first
  gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
  gl.viewport(0, 0, target.width, target.height);
  if (pixel) {
    gl.enable(gl.SCISSOR_TEST);
    gl.scissor(pixel[0], target.height - 1 - pixel[1], 1, 1);
  }
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  if (pixel) gl.disable(gl.SCISSOR_TEST);
}

let frameScale = 1;

// The colour pass: lane group g's radiance (t.radiance) added to the
// colour so far into t.colour[into].
function drawColour(t, g, into) {
  const program = checked(programs.colour);
  gl.useProgram(program);
  gl.bindFramebuffer(gl.FRAMEBUFFER, t.colour[into].framebuffer);
  gl.viewport(0, 0, t.radiance.width, t.radiance.height);
  gl.activeTexture(gl.TEXTURE0);
  gl.bindTexture(gl.TEXTURE_2D, t.radiance.texture);
  gl.activeTexture(gl.TEXTURE1);
  gl.bindTexture(gl.TEXTURE_2D, t.colour[1 - into].texture);
  gl.uniform1i(gl.getUniformLocation(program, 'radiance'), 0);
  gl.uniform1i(gl.getUniformLocation(program, 'previous'), 1);
  gl.uniform1i(gl.getUniformLocation(program, 'first_group'), g === 0 ? 1 : 0);
  const lanes = new Float32Array(12);
  bake.groups[g].manifest.lanes.forEach((lane, i) => lanes.set(lane.preview_linear_srgb, 3 * i));
  gl.uniform3fv(gl.getUniformLocation(program, 'lane_srgb'), lanes);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  gl.activeTexture(gl.TEXTURE0);
}

function drawFrame(resolution) {
  const width = Math.max(1, Math.round(canvas.width * resolution));
  const height = Math.max(1, Math.round(canvas.height * resolution));
  const t = targetsFor(width, height);
  let colour = 0;
  bake.groups.forEach((group, g) => {
    drawRadiance(group, t.radiance);
    drawColour(t, g, colour);
    colour = 1 - colour;
  });
  t.final = t.colour[1 - colour];
  frameScale = resolution;
  display();
}

// One pixel of each pass, the sky's with the program `daylight` says, each
// to be drawn over: a driver that builds a program for the state of its
// first draw (Mesa's llvmpipe: most of a program's compile time) builds it
// now, while the tables download or the viewer waits for input. The sky's
// pixel last, and nothing after it that waits for the driver: the page
// (which unpacks the tables) goes on while the driver builds the program.
let warmUpPixel = null;
function warmUp(daylight, passes) {
  warmUpPixel ??= { radiance: floatTarget(1, 1), colour: [floatTarget(1, 1), floatTarget(1, 1)] };
  if (passes) {
    drawColour(warmUpPixel, 0, 0);
    gl.enable(gl.SCISSOR_TEST);
    gl.scissor(0, 0, 1, 1);
    display(warmUpPixel.colour[0]);
    gl.disable(gl.SCISSOR_TEST);
  }
  drawRadiance(bake.groups[0], warmUpPixel.radiance, [0, 0], daylight);
}

// The last frame's colour (or `source`) on the canvas, at the exposure and
// tone map now set (a change of either redraws only this).
function display(source = targets?.final) {
  if (!source) return;
  const program = checked(programs.display);
  gl.useProgram(program);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  gl.viewport(0, 0, canvas.width, canvas.height);
  gl.activeTexture(gl.TEXTURE0);
  gl.bindTexture(gl.TEXTURE_2D, source.texture);
  gl.uniform1i(gl.getUniformLocation(program, 'preview_srgb'), 0);
  gl.uniform2f(gl.getUniformLocation(program, 'texels_per_pixel'), source.width / canvas.width, source.height / canvas.height);
  gl.uniform1f(gl.getUniformLocation(program, 'exposure'), state.exposure);
  gl.uniform1i(gl.getUniformLocation(program, 'tone_map'), kToneMaps[state.tonemap] ?? 2);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
}

// ---- scheduling: a quarter resolution while the view changes ----
let lastInput = -Infinity;
let pending = null;      // the resolution the next frame is drawn at
let frameWaiters = [];   // resolved when a full-resolution frame is on the canvas
const viewer = {
  loadedMs: null, firstFrameMs: null, fullFrameMs: null, lastFrameMs: null, lastFrameResolution: null, error: null,
};
window.skybakeViewer = viewer;

function requestFrame(resolution) {
  if (viewer.loadedMs === null) return;  // the first frame follows the tables
  if (pending === null) requestAnimationFrame(runFrame);
  pending = Math.min(pending ?? 1, resolution);
}

function runFrame() {
  const resolution = pending;
  pending = null;
  const start = performance.now();
  drawFrame(resolution);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));  // waits for the GPU
  const end = performance.now();
  viewer.lastFrameMs = end - start;
  viewer.lastFrameResolution = resolution;
  viewer.firstFrameMs ??= end;
  statusLine.textContent = `${Math.round(canvas.width * resolution)}×${Math.round(canvas.height * resolution)} in ${Math.round(end - start)} ms` +
    (resolution < 1 ? ' (quarter resolution while the view changes)' : '');
  if (resolution < 1) {
    setTimeout(() => { if (performance.now() - lastInput >= kRestMs) requestFrame(1); }, kRestMs);
  } else {
    if (viewer.fullFrameMs === null) {
      viewer.fullFrameMs = end;
      // The sky program the view does not use yet (the integral along the
      // ray for twilight, or the daylight one), built in the background so
      // that moving the sun across is not held up by it later (linked
      // without blocking the page, then built by its first draw).
      if (!state.moon) {
        const daylight = !daylightView();
        setTimeout(async () => {
          checkedPrograms.add(await linkedProgram(gl, skyProgram(false, daylight, false)));
          if (!state.moon) warmUp(daylight, false);
        }, kRestMs);
      }
    }
    const waiters = frameWaiters;
    frameWaiters = [];
    waiters.forEach((resolve) => resolve());
  }
}

function viewChanged() {
  lastInput = performance.now();
  writeControls();
  history.replaceState(null, '', '?' + new URLSearchParams(Object.entries({
    ...state, ...(fixedSize ? { width: fixedSize[0], height: fixedSize[1] } : {}),
  }).map(([k, v]) => [k, typeof v === 'boolean' ? (v ? '1' : '0') : String(v)])));
  requestFrame(kPreviewScale);
}

// Sets state from `values` and resolves once the full-resolution frame is
// drawn (used by tests and by anyone scripting the page).
viewer.set = (values) => {
  Object.assign(state, values);
  writeControls();
  return new Promise((resolve) => {
    frameWaiters.push(resolve);
    requestFrame(1);
  });
};

// The canvas's RGBA bytes, rows from the top (for tests).
viewer.canvasPixels = () => {
  const { width, height } = canvas;
  const bottomUp = new Uint8Array(width * height * 4);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, bottomUp);
  const rows = [];
  for (let y = height - 1; y >= 0; --y) rows.push(...bottomUp.subarray(y * width * 4, (y + 1) * width * 4));
  return { width, height, rgba: rows };
};

// ---- controls ----
const controls = document.getElementById('controls');
function writeControls() {
  for (const input of controls.querySelectorAll('[data-key]')) {
    const key = input.dataset.key;
    if (key === 'altitude_log') input.value = Math.log10(state.altitude_m + 1) / kTopAltitudeLog_m;
    else if (key === 'exposure_log') input.value = Math.log10(state.exposure);
    else if (input.type === 'checkbox') input.checked = state[key];
    else if (document.activeElement !== input) input.value = state[key];
  }
  const shown = {
    altitude_m: state.altitude_m < 1e4 ? `${state.altitude_m.toFixed(0)} m` : `${(state.altitude_m / 1e3).toPrecision(4)} km`,
    sun_zenith_deg: `${state.sun_zenith_deg.toFixed(1)}°`,
    exposure: state.exposure.toPrecision(3),
  };
  for (const out of controls.querySelectorAll('[data-show]')) out.textContent = shown[out.dataset.show];
}
controls.addEventListener('input', (event) => {
  const input = event.target;
  const key = input.dataset.key;
  if (!key) return;
  const tonemapOnly = key === 'exposure_log' || key === 'tonemap';
  if (key === 'altitude_log') state.altitude_m = Math.round(10 ** (Number(input.value) * kTopAltitudeLog_m) - 1);
  else if (key === 'exposure_log') state.exposure = 10 ** Number(input.value);
  else if (input.type === 'checkbox') state[key] = input.checked;
  else if (input.type === 'number' || input.type === 'range') {
    if (!Number.isFinite(input.valueAsNumber)) return;
    state[key] = input.valueAsNumber;
  } else state[key] = input.value;
  if (tonemapOnly) {
    writeControls();
    display();
    return;
  }
  viewChanged();
});

// ---- dragging: the sun when grabbed near it, otherwise the view ----
let drag = null;
function canvasPoint(event) {
  const r = canvas.getBoundingClientRect();
  return [(event.clientX - r.left) * canvas.width / r.width, (event.clientY - r.top) * canvas.height / r.height];
}
canvas.addEventListener('pointerdown', (event) => {
  const [x, y] = canvasPoint(event);
  const dir = directionAt(x, y, canvas.width, canvas.height);
  const sun = dir && Math.acos(Math.min(1, dot(dir, sunDirection()))) < kSunGrabAngle;
  drag = { sun, x, y };
  canvas.setPointerCapture(event.pointerId);
});
canvas.addEventListener('pointerup', () => { drag = null; });
canvas.addEventListener('pointermove', (event) => {
  const [x, y] = canvasPoint(event);
  if (!drag) {
    readout(x, y);
    return;
  }
  if (drag.sun) {
    const dir = directionAt(x, y, canvas.width, canvas.height);
    if (!dir) return;
    state.sun_zenith_deg = Math.acos(Math.max(-1, Math.min(1, dir[2]))) / kDegree;
    // Fisheye and lat-long images are turned to the sun's azimuth: there
    // the sun moves in zenith only.
    if (state.projection === 'perspective') state.sun_azimuth_deg = Math.atan2(dir[1], dir[0]) / kDegree;
  } else if (state.projection === 'perspective') {
    const degreesPerPixel = 2 * Math.atan(perspectiveFrame(canvas.width, canvas.height).halfWidth) / kDegree / canvas.width;
    state.view_azimuth_deg += (x - drag.x) * degreesPerPixel;
    state.view_elevation_deg = Math.max(-89.9, Math.min(89.9, state.view_elevation_deg + (y - drag.y) * degreesPerPixel));
  } else {
    state.sun_azimuth_deg -= (x - drag.x) * 360 / canvas.width;
  }
  drag.x = x;
  drag.y = y;
  viewChanged();
});
canvas.addEventListener('wheel', (event) => {
  event.preventDefault();
  state.fov_deg = Math.max(1, Math.min(state.projection === 'perspective' ? 179 : 360, state.fov_deg * Math.exp(event.deltaY * 0.001)));
  viewChanged();
}, { passive: false });

// ---- what the cursor sees: every channel's radiance and the luminance ----
function readout(x, y) {
  const out = document.getElementById('readout');
  if (!targets || !directionAt(x, y, canvas.width, canvas.height)) {
    out.textContent = 'outside the image';
    return;
  }
  const pixel = [Math.min(targets.radiance.width - 1, Math.floor(x * frameScale)),
    Math.min(targets.radiance.height - 1, Math.floor(y * frameScale))];
  const names = bake.manifest.channels.names;
  const values = [];
  let luminance = 0;
  for (const group of bake.groups) {
    drawRadiance(group, targets.radiance, pixel);
    const lanes = new Float32Array(4);
    gl.readPixels(pixel[0], targets.radiance.height - 1 - pixel[1], 1, 1, gl.RGBA, gl.FLOAT, lanes);
    group.manifest.lanes.forEach((lane, i) => {
      values.push(`${names[lane.channel]} ${lanes[i].toExponential(3)}`);
      luminance += lane.luminance_cd_m2 * lanes[i];
    });
  }
  const dir = directionAt(x, y, canvas.width, canvas.height);
  const zenith = Math.acos(Math.max(-1, Math.min(1, dir[2]))) / kDegree;
  out.innerHTML = `view zenith ${zenith.toFixed(2)}°, azimuth ${(Math.atan2(dir[1], dir[0]) / kDegree).toFixed(2)}°<br>` +
    `radiance, ${bake.manifest.channels.unit}:<br>${values.join('<br>')}<br>luminance ${luminance.toPrecision(4)} cd m<sup>-2</sup>`;
}

function showFacts(manifest) {
  const f = manifest.facts;
  const rows = [
    ['file', `${f.file} (format ${f.format_version})`], ['atmosphere', f.atmosphere],
    ['channels', manifest.channels.names.join(' ') + (manifest.channels.kind === 'cie_xyz' ? ' (CIE 1931)' : '')],
    ['radii', `${(f.bottom_radius_m / 1e3).toFixed(0)} to ${(f.top_radius_m / 1e3).toFixed(0)} km`],
    ['scattering', f.scattering_size.join(' × ') + ' (r, μ, μs, ν)'], ['orders', f.orders],
  ];
  let html = '<table>' + rows.map(([k, v]) => `<tr><td>${k}</td><td>${v}</td></tr>`).join('') + '</table>';
  if (f.validation) {
    html += `<p>validated against the reference (${f.validation.query_set} set), relative error %, worst channel:</p>` +
      '<table><tr><th></th><th>RMS</th><th>p95</th><th>max</th></tr>' +
      f.validation.errors.map((e) => `<tr><td>${e.quantity.replace('_', ' ')}, ${e.band}</td><td>${e.rms_percent.toFixed(2)}</td>` +
        `<td>${e.p95_percent.toFixed(2)}</td><td>${e.max_percent.toFixed(2)}</td></tr>`).join('') + '</table>';
  } else {
    html += '<p>not validated: <code>skybake validate</code> the bake to see its error here.</p>';
  }
  document.getElementById('facts').innerHTML = html;
}

function resize() {
  const [w, h] = fixedSize ?? [canvas.clientWidth, canvas.clientHeight].map((v) => Math.max(1, Math.round(v * devicePixelRatio)));
  if (canvas.width !== w || canvas.height !== h) {
    canvas.width = w;
    canvas.height = h;
    requestFrame(kPreviewScale);
  }
}

// A context the browser took back (its GPU reset it: on a software
// renderer, work over about 10 s, such as compiling the eclipse shaders)
// cannot draw again: say so rather than show a frozen frame.
canvas.addEventListener('webglcontextlost', (event) => {
  event.preventDefault();
  viewer.error = 'the browser reset WebGL (a frame or shader compile took too long for its GPU watchdog); reload the page';
  statusLine.innerHTML = `<span class="error">${viewer.error}</span>`;
});

let skyPixelsSource = '';
async function start() {
  if (!gl) throw new Error('this browser has no WebGL2');
  if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('this WebGL2 cannot draw into float textures (EXT_color_buffer_float)');
  if (fixedSize) canvas.classList.add('fixed');
  resize();
  new ResizeObserver(resize).observe(canvas);
  const text = (file) => fetch(file).then((r) => {
    if (!r.ok) throw new Error(`${file}: HTTP ${r.status}`);
    return r.text();
  });
  // The display pass needs only the display kernel, not the library.
  const sources = Promise.all([text('sky_pixels.glsl'), text('kernel_language.glsl'), text('display_encoding.glsl')]);
  let warmedUp = Promise.resolve();
  bake = await loadSkybake(gl, 'bake/', {
    onProgress: (n, all) => { statusLine.textContent = `loading the bake: ${n} of ${all} files`; },
    // The programs compiled, and built by a first draw, while the tables download.
    onAllocated: (allocated) => {
      bake = allocated;
      warmedUp = sources.then(async ([pixels, kernelLanguage, displayKernel]) => {
        skyPixelsSource = pixels;
        programs.colour = startProgram(gl, fullScreenVertexShader, colourPassSource);
        programs.display = startProgram(gl, fullScreenVertexShader,
          bake.manifest.glsl.es_header + kernelLanguage + displayKernel + displayMain);
        const sky = skyProgram(state.moon, daylightView(), false);
        for (const program of [programs.colour, programs.display, sky]) checkedPrograms.add(await linkedProgram(gl, program));
        if (!state.moon) warmUp(daylightView(), true);  // an eclipse's first draw needs the tables
      });
    },
  });
  await warmedUp;
  viewer.loadedMs = performance.now();
  // The first frame now rather than at the next animation frame.
  pending = kPreviewScale;
  runFrame();
  showFacts(bake.manifest);
  writeControls();
}
viewer.ready = start().catch((error) => {
  viewer.error = String(error.message ?? error);
  statusLine.innerHTML = `<span class="error">${viewer.error}</span>`;
  console.error(error);
});
