"""Chromium with WebGL2 for skybake's browser test and benchmark
(tests/browser/browser_view_test.py, scripts/bench_view.py): an Xvfb
display of its own, and Chromium driven by Selenium with its WebGL2 on
Mesa's llvmpipe there (ANGLE over desktop GL: the renderer `skybake render
--backend gl` uses on a machine without a GPU), or headless on SwiftShader
where that cannot start. Needs Debian's chromium, chromium-driver,
python3-selenium and xvfb (scripts/setup.sh installs them)."""
import os
import shutil
import subprocess

CHROMIUM = '/usr/bin/chromium'
CHROMEDRIVER = '/usr/bin/chromedriver'


def missing():
    """Why Chromium cannot be driven here, or None."""
    try:
        import selenium  # noqa: F401
    except ImportError:
        return 'python3-selenium is not installed (scripts/setup.sh installs it)'
    for program in (CHROMIUM, CHROMEDRIVER):
        if not os.access(program, os.X_OK):
            return f'{program} is not installed (scripts/setup.sh installs chromium and chromium-driver)'
    return None


class Xvfb:
    """An X display of our own (`display`, None where Xvfb is missing or
    fails), stopped by its PID on close()."""

    def __init__(self, screen='1920x1080x24'):
        self.process, self.display = None, None
        if not shutil.which('Xvfb'):
            return
        read, write = os.pipe()
        self.process = subprocess.Popen(['Xvfb', '-displayfd', str(write), '-screen', '0', screen, '-nolisten', 'tcp'],
                                        pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(write)
        with os.fdopen(read) as f:
            number = f.readline().strip()
        if number:
            self.display = ':' + number
        else:
            self.close()

    def close(self):
        if self.process:
            self.process.terminate()
            self.process.wait()
            self.process = None


def webgl_chromium(display, window=(800, 600), script_timeout_s=300):
    """(driver, renderer name) for Chromium with WebGL2, or (None, reasons)."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    attempts = []
    if display:
        # The GPU watchdog resets a context whose work takes more than
        # about 10 s; llvmpipe compiles the eclipse shaders for longer.
        attempts.append(('llvmpipe (ANGLE over Mesa GL, Xvfb)',
                         ['--use-gl=angle', '--use-angle=gl', '--ignore-gpu-blocklist', '--disable-gpu-watchdog'],
                         display))
    attempts.append(('SwiftShader (headless)',
                     ['--headless=new', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'], None))
    errors = []
    for name, flags, disp in attempts:
        options = webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        # --disable-dev-shm-usage: containers often give /dev/shm 64 MiB,
        # less than a bake's textures on their way to the GPU process.
        for flag in ['--no-sandbox', '--disable-dev-shm-usage', f'--window-size={window[0]},{window[1]}', *flags]:
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
        driver.set_script_timeout(script_timeout_s)
        driver.get('about:blank')
        if driver.execute_script("return !!document.createElement('canvas').getContext('webgl2');"):
            return driver, name
        errors.append(f'{name}: no WebGL2')
        driver.quit()
    return None, '; '.join(errors)


def start_viewer(skybake, bake, extra=()):
    """`skybake view BAKE --no-open --port 0` and its URL."""
    process = subprocess.Popen([skybake, 'view', bake, '--no-open', '--port', '0', *extra], stdout=subprocess.PIPE,
                               text=True)
    line = process.stdout.readline()
    if ' at ' not in line:
        process.kill()
        raise RuntimeError(f'skybake view did not start: {line!r}')
    return process, line.split(' at ')[1].split()[0]


# Resolves with the viewer's error (null when it loaded) once its page has
# loaded the bake and compiled its shaders.
WAIT_FOR_VIEWER = '''const done = arguments[0];
const wait = () => window.skybakeViewer && window.skybakeViewer.ready
  ? window.skybakeViewer.ready.then(() => done(window.skybakeViewer.error)) : setTimeout(wait, 20);
wait();'''
