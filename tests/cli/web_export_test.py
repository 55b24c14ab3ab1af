#!/usr/bin/python3
"""skybake export --format web: the manifest states every file and what it
holds, the tables unpack to the GPU upload's bytes (the manifest's sizes
and formats), the export is at most that upload's size, and folders that
hold anything else are refused; skybake view's refusals of bad input.

Usage: web_export_test.py SKYBAKE BAKE WORK_DIR"""
import gzip
import json
import os
import re
import shutil
import subprocess
import sys

skybake, bake, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures, passed = [], 0


def check(ok, what):
    global passed
    if ok:
        passed += 1
    else:
        failures.append(what)
        print(f'FAILED: {what}')


out = os.path.join(work, 'web')
run = subprocess.run([skybake, 'export', bake, '--format', 'web', '-o', out], capture_output=True, text=True)
check(run.returncode == 0, f'export exits 0 ({run.stderr.strip()})')
manifest = json.load(open(os.path.join(out, 'manifest.json')))
check(manifest['format'] == 'skybake-web' and manifest['version'] == 1, 'the manifest names its format')
texel_bytes = {('RGBA32F', 'FLOAT'): 16, ('RGB16F', 'HALF_FLOAT'): 6, ('RGBA16F', 'HALF_FLOAT'): 8}
unpacked = 0
for group in manifest['groups']:
    block = group['uniform_block']
    check(sum(16 * m['count'] for m in block['members']) == block['bytes'] and
          all(len(m['values']) == 4 * m['count'] for m in block['members']),
          'the uniform block\'s members fill its std140 bytes')
    samplers = [t['sampler'] for t in group['textures']]
    check(samplers == ['skybake_optical_depth', 'skybake_single_rayleigh', 'skybake_single_mie',
                       'skybake_multiple_scattering', 'skybake_multiple_density', 'skybake_irradiance',
                       'skybake_slice_scales'], f'the textures are the GLSL library\'s samplers in order ({samplers})')
    for t in group['textures']:
        data = gzip.decompress(open(os.path.join(out, t['file']), 'rb').read())
        w, h, d = t['size']
        expected = w * h * d * texel_bytes[(t['internal_format'], t['type'])]
        check(len(data) == t['bytes'] == expected, f'{t["file"]} unpacks to its {w}x{h}x{d} texels ({len(data)} bytes)')
        unpacked += len(data)
    check(len(group['lanes']) == len(manifest['channels']['names']) or len(manifest['groups']) > 1,
          'every channel has a lane')
# skybake info states the half upload in MiB (one decimal): the unpacked
# textures are that upload (its 4D tables and 2D tables as uploaded).
info = subprocess.run([skybake, 'info', bake], capture_output=True, text=True).stdout
upload_mib = float(re.search(r'GPU upload:\s+([0-9.]+) MiB half', info).group(1))
check(abs(unpacked / 2**20 - upload_mib) <= 0.05 + 1e-9,
      f'the textures unpack to the half-float GPU upload ({unpacked / 2**20:.3f} MiB, info says {upload_mib})')
total = sum(os.path.getsize(os.path.join(out, f)) for f in os.listdir(out))
check(total <= unpacked, f'the export ({total} bytes) is at most its GPU upload ({unpacked} bytes)')
glsl = open(os.path.join(out, manifest['glsl']['file'])).read()
check('skybakeSkyRadiance' in glsl and '#define SKYBAKE_GAUSS_NODES' in glsl, 'the GLSL library is there, defines first')

again = subprocess.run([skybake, 'export', bake, '--format', 'web', '-o', out], capture_output=True, text=True)
check(again.returncode == 0, 'an earlier export is replaced')
other = os.path.join(work, 'other')
os.makedirs(other)
open(os.path.join(other, 'notes.txt'), 'w').write('mine')
refused = subprocess.run([skybake, 'export', bake, '--format', 'web', '-o', other], capture_output=True, text=True)
check(refused.returncode == 2 and other in refused.stderr and 'not a skybake web export' in refused.stderr,
      f'a folder of other files is refused with exit 2 naming it ({refused.stderr.strip()})')
check(os.listdir(other) == ['notes.txt'], 'and nothing is written there')
bad_format = subprocess.run([skybake, 'export', bake, '--format', 'gltf', '-o', out], capture_output=True, text=True)
check(bad_format.returncode == 2, 'an unknown --format is refused with exit 2')

# skybake view's refusals (its page is tests/browser's): a missing bake, a
# port out of range, a port another program holds; exit 2 and the reason.
import socket  # noqa: E402
missing = subprocess.run([skybake, 'view', os.path.join(work, 'none.exr'), '--no-open'], capture_output=True, text=True)
check(missing.returncode == 2 and 'none.exr' in missing.stderr, f'view refuses a missing bake ({missing.stderr.strip()})')
far = subprocess.run([skybake, 'view', bake, '--no-open', '--port', '70000'], capture_output=True, text=True)
check(far.returncode == 2 and '70000' in far.stderr, f'view refuses port 70000 ({far.stderr.strip()})')
with socket.socket() as taken:
    taken.bind(('127.0.0.1', 0))
    taken.listen()
    port = taken.getsockname()[1]
    busy = subprocess.run([skybake, 'view', bake, '--no-open', '--port', str(port)], capture_output=True, text=True,
                          timeout=120)
check(busy.returncode == 2 and str(port) in busy.stderr and 'in use' in busy.stderr,
      f'view refuses a port in use, naming it ({busy.stderr.strip()})')

print(f'web_export: {passed} passed, {len(failures)} failed')
sys.exit(1 if failures else 0)
