#!/usr/bin/python3
"""skybake view and the web export in a real browser (Chromium through
Selenium): the viewer's canvas against `skybake render --backend gl` of the
same views, the plain WebGL2 example against `skybake lookup radiance`, the
server's refusal of paths outside its files and its clean stop on Ctrl-C.
Any console error, or GL error WebGL reports, fails the test.

Chromium runs its WebGL2 on Mesa's llvmpipe (ANGLE over desktop GL, in an
Xvfb display the test starts), the renderer `skybake render --backend gl`
uses; where that cannot start, on SwiftShader, headless. Where Chromium,
ChromeDriver, Selenium or Xvfb is missing the test prints SKIPPED and why.

Usage: browser_view_test.py SKYBAKE BAKE COLOUR_BAKE SPECTRAL_CONFIG WORK_DIR
(a 3-wavelength bake, a colour bake, and a spectral bake's config, which
the test bakes)"""
import http.client
import os
import shutil
import signal
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scripts'))
import browser_session  # noqa: E402

SIZE = (96, 64)  # small: llvmpipe draws every pixel on the CPU


def skip(reason):
    print(f'browser_view: SKIPPED: {reason}')
    sys.exit(0)


if browser_session.missing():
    skip(browser_session.missing())

skybake, bake, colour_bake, spectral_config, work = sys.argv[1:6]
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


def console_errors(driver):
    """Errors, and the GL errors WebGL reports as warnings (a draw it refused
    draws nothing)."""
    return [e['message'] for e in driver.get_log('browser')
            if e['level'] == 'SEVERE' or 'GL_INVALID' in e['message'] or 'WebGL:' in e['message']]


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


def show(driver, state):
    """The canvas's RGB levels once the page has drawn `state` in full."""
    driver.execute_async_script('window.skybakeViewer.set(arguments[0]).then(arguments[1]);', state)
    shot = driver.execute_script('return window.skybakeViewer.canvasPixels();')
    return numpy.array(shot['rgba'], dtype=int).reshape(shot['height'], shot['width'], 4)[:, :, :3]


def compare_views(driver, bake_path, views, label):
    """Each view on the page (already showing `bake_path`) against render --backend gl."""
    for i, (state, options) in enumerate(views):
        state = dict({'sun_disk': False, 'moon': False}, **state)
        page = show(driver, state)
        png = os.path.join(work, f'{label}{i}.png')
        subprocess.run([skybake, 'render', bake_path, '--backend', 'gl', '--no-sun', '--size', f'{SIZE[0]}x{SIZE[1]}',
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
              f'{label} view {i} ({state["projection"]}, sun {state["sun_zenith_deg"]} deg, {state["tonemap"]}'
              f'{", moon" if state["moon"] else ""}): the canvas matches render --backend gl '
              f'(max {difference.max()}, mean {difference.mean():.3f} levels)')
        check(rendered.mean() > 8, f'{label} view {i} is not black (mean level {rendered.mean():.1f})')


def open_viewer(driver, bake_path):
    """skybake view of `bake_path` loaded in the browser: its process and URL."""
    process, url = browser_session.start_viewer(skybake, bake_path)
    driver.get(f'{url}?width={SIZE[0]}&height={SIZE[1]}')
    ready = driver.execute_async_script(browser_session.WAIT_FOR_VIEWER)
    check(ready is None, f'the viewer loads {os.path.basename(bake_path)} ({ready})')
    return process, url


def stop(process):
    process.send_signal(signal.SIGINT)  # Ctrl-C
    try:
        rest = process.communicate(timeout=10)[0]
        check(process.returncode == 0 and 'stopped' in rest, 'skybake view stops cleanly on Ctrl-C (exit 0)')
    except subprocess.TimeoutExpired:
        process.kill()
        check(False, 'skybake view stops on Ctrl-C within 10 s')



here = os.path.dirname(os.path.abspath(__file__))
xvfb = browser_session.Xvfb()
viewer = None
example_server = None
driver = None
try:
    # ---- skybake view ----
    viewer, url = browser_session.start_viewer(skybake, bake)
    port = int(url.rsplit(':', 1)[1].strip('/'))
    print(f'viewer: {url}')
    check(get(port, '/') == 200 and get(port, '/bake/manifest.json') == 200, 'the page and the export are served')
    for path in ['/../../etc/passwd', '/bake/../CMakeLists.txt', '/%2e%2e/%2e%2e/etc/passwd', '/bake/earth.exr']:
        check(get(port, path) == 404, f'{path} is refused (404)')

    driver, renderer = browser_session.webgl_chromium(xvfb.display)
    if not driver:
        skip(f'Chromium does not start with WebGL2 here: {renderer}')
    print(f'browser: Chromium with WebGL2 on {renderer}')
    driver.get(f'{url}?width={SIZE[0]}&height={SIZE[1]}')
    ready = driver.execute_async_script(browser_session.WAIT_FOR_VIEWER)
    check(ready is None, f'the viewer loads {os.path.basename(bake)} ({ready})')

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
        # A partial eclipse: the moon's eclipse shaders and skylight pass.
        ({'projection': 'fisheye', 'altitude_m': 0, 'sun_zenith_deg': 50, 'sun_azimuth_deg': 0, 'fov_deg': 180,
          'exposure': 10, 'tonemap': 'aces', 'moon': True, 'moon_azimuth_deg': 0, 'moon_elevation_deg': 40.1,
          'moon_radius_deg': 0.28},
         ['--projection', 'fisheye', '--altitude-m', '0', '--sun-zenith-deg', '50', '--fov-deg', '180',
          '--exposure', '10', '--tonemap', 'aces', '--moon', '0,40.1,0.28']),
    ]
    compare_views(driver, bake, views, 'wavelengths')

    # The sun disk the page draws itself: a view looking at the sun has a
    # saturated pixel (the disk is 1e5 times the sky's radiance; at
    # exposure 1 the sky around it stays below white).
    page = show(driver, {'projection': 'perspective', 'altitude_m': 0, 'sun_zenith_deg': 60, 'sun_azimuth_deg': 0,
                         'view_azimuth_deg': 0, 'view_elevation_deg': 30, 'fov_deg': 20, 'exposure': 1,
                         'tonemap': 'none', 'sun_disk': True, 'moon': False})
    check(page.sum(axis=2).max() == 3 * 255 and numpy.median(page.sum(axis=2)) < 3 * 255,
          'the sun disk shows (saturated) in a sky that is not')
    errors = console_errors(driver)
    check(not errors, f'no console errors in the viewer ({errors})')
    stop(viewer)
    viewer = None

    # ---- colour as render makes it, from X, Y, Z and from lane groups ----
    # A colour bake, in daylight and in twilight (its wavelength passes).
    colour_viewer, _ = open_viewer(driver, colour_bake)
    compare_views(driver, colour_bake, [
        ({'projection': 'perspective', 'altitude_m': 0, 'sun_zenith_deg': 60, 'sun_azimuth_deg': 0,
          'view_azimuth_deg': 0, 'view_elevation_deg': 10, 'fov_deg': 90, 'exposure': 10, 'tonemap': 'aces'},
         ['--projection', 'perspective', '--altitude-m', '0', '--sun-zenith-deg', '60', '--view-elevation-deg', '10',
          '--exposure', '10']),
        ({'projection': 'fisheye', 'altitude_m': 0, 'sun_zenith_deg': 95, 'sun_azimuth_deg': 0, 'fov_deg': 180,
          'exposure': 3000, 'tonemap': 'aces'},
         ['--projection', 'fisheye', '--altitude-m', '0', '--sun-zenith-deg', '95', '--exposure', '3000'])], 'colour')
    stop(colour_viewer)
    # A spectral bake of 6 wavelengths: two lane groups summed into colour.
    spectral = os.path.join(work, 'spectral.exr')
    config = open(spectral_config).read().replace('../../data_formats', os.path.join(here, '..', '..', 'data_formats'))
    with open(os.path.join(work, 'spectral.toml'), 'w') as f:
        f.write(config)
    subprocess.run([skybake, 'bake', os.path.join(work, 'spectral.toml'), '-o', spectral], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    spectral_viewer, _ = open_viewer(driver, spectral)
    compare_views(driver, spectral, [
        ({'projection': 'perspective', 'altitude_m': 500, 'sun_zenith_deg': 75, 'sun_azimuth_deg': 30,
          'view_azimuth_deg': 0, 'view_elevation_deg': 5, 'fov_deg': 100, 'exposure': 10, 'tonemap': 'reinhard'},
         ['--projection', 'perspective', '--altitude-m', '500', '--sun-zenith-deg', '75', '--sun-azimuth-deg', '30',
          '--view-azimuth-deg', '0', '--view-elevation-deg', '5', '--fov-deg', '100', '--exposure', '10',
          '--tonemap', 'reinhard'])], 'spectral')
    stop(spectral_viewer)
    errors = console_errors(driver)
    check(not errors, f'no console errors in the colour and spectral viewers ({errors})')

    # ---- the plain WebGL2 example on an export ----
    site = os.path.join(work, 'site')
    os.makedirs(site)
    subprocess.run([skybake, 'export', bake, '--format', 'web', '-o', os.path.join(site, 'bake')], check=True,
                   stdout=subprocess.DEVNULL)
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
        stop(viewer)
    xvfb.close()

print(f'browser_view: {passed} passed, {len(failures)} failed')
sys.exit(1 if failures else 0)
