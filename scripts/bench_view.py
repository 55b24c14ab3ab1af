"""The measurements of scripts/bench_view.sh (its header says what they
are). Usage: bench_view.py SKYBAKE BAKE RUNS"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import browser_session  # noqa: E402

skybake, bake, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
WIDTH, HEIGHT = 1280, 720
# The README's preview view: on the ground looking toward a sun 80 deg from
# the zenith.
VIEW = {'projection': 'perspective', 'altitude_m': 0, 'sun_zenith_deg': 80, 'sun_azimuth_deg': 0,
        'view_azimuth_deg': 0, 'view_elevation_deg': 20, 'fov_deg': 90, 'exposure': 10, 'tonemap': 'aces',
        'sun_disk': True}
RENDER = ['--projection', 'perspective', '--altitude-m', '0', '--sun-zenith-deg', '80', '--view-elevation-deg', '20',
          '--size', f'{WIDTH}x{HEIGHT}']
FRAMES = 5  # full frames timed per run

if browser_session.missing():
    sys.exit(f'bench_view: {browser_session.missing()}')
xvfb = browser_session.Xvfb()
viewer, url = browser_session.start_viewer(skybake, bake)
query = '&'.join(f'{k}={int(v) if isinstance(v, bool) else v}' for k, v in VIEW.items())
page = f'{url}?{query}&width={WIDTH}&height={HEIGHT}'
first_frame = {'cold': [], 'warm': []}
full_frame = {'cold': [], 'warm': []}
frame_s = []
renderer = None
try:
    for cache in ('cold', 'warm'):
        with tempfile.TemporaryDirectory() as cold_cache:
            for run in range(runs):
                # Mesa keeps compiled shaders on disk: an empty cache per
                # run is a machine's first run, the user's own cache after.
                os.environ['MESA_SHADER_CACHE_DIR'] = (tempfile.mkdtemp(dir=cold_cache) if cache == 'cold'
                                                       else os.path.expanduser('~/.cache/mesa_shader_cache'))
                driver, renderer = browser_session.webgl_chromium(xvfb.display, window=(WIDTH + 400, HEIGHT + 200))
                if not driver:
                    sys.exit(f'bench_view: Chromium does not start with WebGL2: {renderer}')
                driver.get(page)
                error = driver.execute_async_script(browser_session.WAIT_FOR_VIEWER)
                if error:
                    sys.exit(f'bench_view: the viewer failed: {error}')
                times = driver.execute_async_script('''const done = arguments[0], v = window.skybakeViewer;
                  const wait = () => v.fullFrameMs ? done([v.firstFrameMs, v.fullFrameMs]) : setTimeout(wait, 20);
                  wait();''')
                first_frame[cache].append(times[0] / 1e3)
                full_frame[cache].append(times[1] / 1e3)
                if cache == 'warm':
                    for _ in range(FRAMES):
                        driver.execute_async_script('window.skybakeViewer.set(arguments[0]).then(arguments[1]);',
                                                    VIEW)
                        frame_s.append(driver.execute_script('return window.skybakeViewer.lastFrameMs;') / 1e3)
                driver.quit()
    os.environ.pop('MESA_SHADER_CACHE_DIR')
    render = {}
    for backend in ('cpu', 'gl'):
        seconds = []
        for _ in range(runs):
            start = time.monotonic()
            subprocess.run([skybake, 'render', bake, *RENDER, '--backend', backend, '-o',
                            os.path.join(tempfile.gettempdir(), f'bench_view_{backend}.png')], check=True,
                           stdout=subprocess.DEVNULL)
            seconds.append(time.monotonic() - start)
        render[backend] = statistics.median(seconds)
finally:
    viewer.terminate()
    viewer.wait()
    xvfb.close()

median = statistics.median
print(f'browser: Chromium, WebGL2 on {renderer}; view: {WIDTH}x{HEIGHT}, ground, sun 80 deg, perspective 90 deg')
print(f'page navigation to first frame (quarter resolution): {median(first_frame["cold"]):.2f} s with Mesa\'s '
      f'shader cache empty, {median(first_frame["warm"]):.2f} s filled')
print(f'page navigation to the full-resolution frame:        {median(full_frame["cold"]):.2f} s empty, '
      f'{median(full_frame["warm"]):.2f} s filled')
print(f'full {WIDTH}x{HEIGHT} frames on llvmpipe: {median(frame_s):.2f} s each, {1 / median(frame_s):.2f} frames/s '
      f'(median of {len(frame_s)})')
print(f'skybake render, the same view (whole process): CPU {render["cpu"]:.2f} s, --backend gl {render["gl"]:.2f} s')
