#!/usr/bin/python3
"""skybake view and the web export in a real browser (Chromium through
Selenium): the viewer's canvas against `skybake render --backend gl` of the
same views, the plain WebGL2 example against `skybake lookup radiance`, the
server's refusal of paths outside its files and its clean stop on Ctrl-C.
Any console error fails the test.

Chromium runs its WebGL2 on Mesa's llvmpipe (ANGLE over desktop GL, in an
Xvfb display the test starts), the renderer `skybake render --backend gl`
uses; where that cannot start, on SwiftShader, headless. Where Chromium,
ChromeDriver, Selenium or Xvfb is missing the test prints SKIPPED and why.

Usage: browser_view_test.py SKYBAKE BAKE WORK_DIR"""
import base64
import http.client
import json
import os
import shutil
import signal
import subprocess
import sys
import time

CHROMIUM = '/usr/bin/chromium'
CHROMEDRIVER = '/usr/bin/chromedriver'
# Every shader is compiled the first time (llvmpipe takes about 10 s for the
# sky's; SwiftShader longer): generous, the views themselves take a second.
SCRIPT_TIMEOUT_S = 300
SIZE = (96, 64)  # small: llvmpipe draws every pixel on the CPU


def skip(reason):
    print(f'browser_view: SKIPPED: {reason}')
    sys.exit(0)


try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
except ImportError:
    skip('python3-selenium is not installed (scripts/setup.sh installs it)')
for program in (CHROMIUM, CHROMEDRIVER):
    if not os.access(program, os.X_OK):
        skip(f'{program} is not installed (scripts/setup.sh installs chromium and chromium-driver)')

skybake, bake, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []
passed = 0


def check(ok, what):
    global passed
    if ok:
        passed += 1
        print(f'  ok: {what}')
    else:
        failures.append(what)
        print(f'  FAILED: {what}')


def start_xvfb():
    """An X display of our own, or None where Xvfb is missing or fails."""
    if not shutil.which('Xvfb'):
        return None, None
    read, write = os.pipe()
    process = subprocess.Popen(['Xvfb', '-displayfd', str(write), '-screen', '0', '1024x768x24', '-nolisten', 'tcp'],
                               pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write)
    with os.fdopen(read) as f:
        display = f.readline().strip()
    if not display:
        process.kill()
        return None, None
    return process, ':' + display


def browser(display):
    """Chromium on llvmpipe under `display`, else headless on SwiftShader."""
    attempts = []
    if display:
        attempts.append(('llvmpipe (ANGLE over Mesa GL, Xvfb)',
                         ['--use-gl=angle', '--use-angle=gl', '--ignore-gpu-blocklist'], display))
    attempts.append(('SwiftShader (headless)', ['--headless=new', '--use-angle=swiftshader',
                                                '--enable-unsafe-swiftshader'], None))
    errors = []
    for name, flags, disp in attempts:
        options = webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        for flag in ['--no-sandbox', '--window-size=800,600', *flags]:
            options.add_argument(flag)
        options.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
        env = dict(os.environ)
        if disp:
            env['DISPLAY'] = disp
        try:
            driver = webdriver.Chrome(service=Service(CHROMEDRIVER, env=env), options=options)
        except Exception as e:  # a browser that cannot start here
            errors.append(f'{name}: {str(e).splitlines()[0]}')
            continue
        driver.set_script_timeout(SCRIPT_TIMEOUT_S)
        driver.get('about:blank')
        has_webgl2 = driver.execute_script("return !!document.createElement('canvas').getContext('webgl2');")
        if has_webgl2:
            print(f'browser: Chromium with WebGL2 on {name}')
            return driver
        errors.append(f'{name}: no WebGL2')
        driver.quit()
    skip('Chromium does not start with WebGL2 here: ' + '; '.join(errors))


def console_errors(driver):
    return [e['message'] for e in driver.get_log('browser') if e['level'] == 'SEVERE']


def read_png(path):
    """RGB bytes of an 8-bit PNG (matplotlib reads it as floats in [0, 1])."""
    import matplotlib.image
    import numpy
    return numpy.rint(matplotlib.image.imread(path)[:, :, :3] * 255.0).astype(int)


def get(port, path):
    """The status of GET `path` sent as it is (no client-side normalising)."""
    connection = http.client.HTTPConnection('127.0.0.1', port, timeout=10)
    connection.putrequest('GET', path, skip_host=False, skip_accept_encoding=True)
    connection.endheaders()
    status = connection.getresponse().status
    connection.close()
    return status


import numpy  # noqa: E402  (after the skips: python3-numpy is a test package too)

xvfb, display = start_xvfb()
viewer = None
example_server = None
driver = None
try:
    # ---- skybake view ----
    viewer = subprocess.Popen([skybake, 'view', bake, '--no-open', '--port', '0'], stdout=subprocess.PIPE, text=True)
    line = viewer.stdout.readline()
    url = line.split(' at ')[1].split()[0]
    port = int(url.rsplit(':', 1)[1].strip('/'))
    print(f'viewer: {url}')
    check(get(port, '/') == 200 and get(port, '/bake/manifest.json') == 200, 'the page and the export are served')
    for path in ['/../../etc/passwd', '/bake/../CMakeLists.txt', '/%2e%2e/%2e%2e/etc/passwd', '/bake/earth.exr']:
        check(get(port, path) == 404, f'{path} is refused (404)')

    driver = browser(display)
    driver.get(f'{url}?width={SIZE[0]}&height={SIZE[1]}')
    ready = driver.execute_async_script('''const done = arguments[0];
      const wait = () => window.skybakeViewer && window.skybakeViewer.ready
        ? window.skybakeViewer.ready.then(() => done(window.skybakeViewer.error)) : setTimeout(wait, 20);
      wait();''')
    check(ready is None, f'the viewer loads the bake ({ready})')

    # The views: the page's state and the same view as render's options.
    # The sun disk is left out of both: render integrates it exactly over
    # each pixel, the page samples it (sky_pixels.glsl).
    views = [
        ({'projection': 'perspective', 'altitude_m': 0, 'sun_zenith_deg': 70, 'sun_azimuth_deg': 20,
          'view_azimuth_deg': 0, 'view_elevation_deg': 10, 'fov_deg': 90, 'exposure': 10, 'tonemap': 'aces'},
         ['--projection', 'perspective', '--altitude-m', '0', '--sun-zenith-deg', '70', '--sun-azimuth-deg', '20',
          '--view-azimuth-deg', '0', '--view-elevation-deg', '10', '--fov-deg', '90', '--exposure', '10',
          '--tonemap', 'aces']),
        ({'projection': 'fisheye', 'altitude_m': 2000, 'sun_zenith_deg': 93, 'sun_azimuth_deg': 0, 'fov_deg': 180,
          'exposure': 3000, 'tonemap': 'reinhard'},
         ['--projection', 'fisheye', '--altitude-m', '2000', '--sun-zenith-deg', '93', '--fov-deg', '180',
          '--exposure', '3000', '--tonemap', 'reinhard']),
        ({'projection': 'latlong', 'altitude_m': 30000, 'sun_zenith_deg': 45, 'sun_azimuth_deg': -60,
          'exposure': 5, 'tonemap': 'none'},
         ['--projection', 'latlong', '--altitude-m', '30000', '--sun-zenith-deg', '45', '--sun-azimuth-deg', '-60',
          '--exposure', '5', '--tonemap', 'none']),
    ]
    for i, (state, options) in enumerate(views):
        state = dict(state, sun_disk=False, moon=False)
        driver.execute_async_script('window.skybakeViewer.set(arguments[0]).then(arguments[1]);', state)
        shot = driver.execute_script('return window.skybakeViewer.canvasPixels();')
        page = numpy.array(shot['rgba'], dtype=int).reshape(shot['height'], shot['width'], 4)[:, :, :3]
        png = os.path.join(work, f'view{i}.png')
        subprocess.run([skybake, 'render', bake, '--backend', 'gl', '--no-sun', '--size', f'{SIZE[0]}x{SIZE[1]}',
                        *options, '-o', png], check=True, stdout=subprocess.DEVNULL)
        rendered = read_png(png)
        difference = numpy.abs(page - rendered)
        # The same GLSL on the same float arithmetic (llvmpipe both): the
        # radiances agree to a few float roundings (ANGLE's translation may
        # contract a*b+c differently), which moves an 8-bit value by at
        # most one level; the page's colour sum is in float where render's
        # is in double (1e-7), and GL's float-to-byte conversion may round a
        # half level the other way from render's lround: at most 2 levels
        # anywhere, and on average far below one.
        check(difference.max() <= 2 and difference.mean() <= 0.25,
              f'view {i} ({state["projection"]}, sun {state["sun_zenith_deg"]} deg, {state["tonemap"]}): '
              f'the canvas matches render --backend gl (max {difference.max()}, mean {difference.mean():.3f} levels)')
        check(rendered.mean() > 8, f'view {i} is not black (mean level {rendered.mean():.1f})')

    # The sun disk the page draws itself: a view looking at the sun has a
    # pixel far brighter than the sky beside it.
    driver.execute_async_script('window.skybakeViewer.set(arguments[0]).then(arguments[1]);',
                                {'projection': 'perspective', 'altitude_m': 0, 'sun_zenith_deg': 60,
                                 'sun_azimuth_deg': 0, 'view_azimuth_deg': 0, 'view_elevation_deg': 30,
                                 'fov_deg': 20, 'exposure': 10, 'tonemap': 'none', 'sun_disk': True})
    shot = driver.execute_script('return window.skybakeViewer.canvasPixels();')
    page = numpy.array(shot['rgba'], dtype=int).reshape(shot['height'], shot['width'], 4)[:, :, :3]
    check(page.sum(axis=2).max() == 3 * 255 and numpy.median(page.sum(axis=2)) < 3 * 255,
          'the sun disk shows (saturated) in a sky that is not')
    errors = console_errors(driver)
    check(not errors, f'no console errors in the viewer ({errors})')

    # ---- the plain WebGL2 example on an export ----
    site = os.path.join(work, 'site')
    os.makedirs(site)
    subprocess.run([skybake, 'export', bake, '--format', 'web', '-o', os.path.join(site, 'bake')], check=True,
                   stdout=subprocess.DEVNULL)
    here = os.path.dirname(os.path.abspath(__file__))
    web = os.path.join(here, '..', '..', 'runtime', 'glsl', 'web')
    for name in ('example.html', 'skybake_web.js'):
        shutil.copy(os.path.join(web, name), site)
    example_server = subprocess.Popen(['/usr/bin/python3', '-m', 'http.server', '--bind', '127.0.0.1', '0'],
                                      cwd=site, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    served = example_server.stdout.readline()  # "Serving HTTP on 127.0.0.1 port N ..."
    example_port = int(served.split(' port ')[1].split()[0])
    driver.get(f'http://127.0.0.1:{example_port}/example.html?bake=bake/')
    result = driver.execute_async_script('''const done = arguments[0];
      const wait = () => window.skybakeExample ? done(window.skybakeExample) : setTimeout(wait, 20);
      wait();''')
    check('error' not in result, f'the example loads the export ({result.get("error")})')
    queries = os.path.join(work, 'zenith.csv')
    with open(queries, 'w') as f:
        f.write('altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg\n1000,30,0,0\n')
    lookup = subprocess.run([skybake, 'lookup', 'radiance', bake, '--queries', queries], check=True, capture_output=True,
                            text=True).stdout.strip().splitlines()
    header, values = lookup[0].split(','), lookup[1].split(',')
    # radiance_<wavelength> columns, in the bake's channel order as the manifest's.
    cpu = [float(v) for h, v in zip(header, values) if h.startswith('radiance_')]
    gpu = result.get('radiance', [])
    # GLSL in float against the CPU lookup in double: tests/gl holds the
    # library to 0.03 % RMS on its views; 0.1 % per channel here.
    check(len(cpu) == len(gpu) > 0 and all(abs(g - c) <= 1e-3 * abs(c) for g, c in zip(gpu, cpu)),
          f'the example\'s zenith radiance {gpu} equals skybake lookup\'s {cpu} to 0.1 %')
    errors = console_errors(driver)
    check(not errors, f'no console errors in the example ({errors})')
finally:
    if driver:
        driver.quit()
    if example_server:
        example_server.terminate()
        example_server.wait()
    if viewer:
        viewer.send_signal(signal.SIGINT)  # Ctrl-C
        try:
            rest = viewer.communicate(timeout=10)[0]
            check(viewer.returncode == 0 and 'stopped' in rest, 'skybake view stops cleanly on Ctrl-C (exit 0)')
        except subprocess.TimeoutExpired:
            viewer.kill()
            check(False, 'skybake view stops on Ctrl-C within 10 s')
    if xvfb:
        xvfb.terminate()
        xvfb.wait()

print(f'browser_view: {passed} passed, {len(failures)} failed')
sys.exit(1 if failures else 0)
