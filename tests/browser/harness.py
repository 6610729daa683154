"""What the browser test, the screenshot and the benchmark share: `quaternia explore` on a free
loopback port, and Debian's chromium driven headless through Selenium and chromedriver (Debian's
python3-selenium and chromium-driver, which matches Debian's chromium). The flags keep chromium
off the network and out of the user's profile."""
import base64
import os
import re
import shutil
import signal
import socket
import subprocess
import tempfile
import threading
import time

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.support.ui import WebDriverWait

CHROMIUM = os.environ.get("QUATERNIA_CHROMIUM", "/usr/bin/chromium")
CHROMEDRIVER = os.environ.get("QUATERNIA_CHROMEDRIVER", "/usr/bin/chromedriver")
# Chromium and chromedriver start in a few seconds; a browser that has not by then will not.
BROWSER_START_SECONDS = float(os.environ.get("QUATERNIA_BROWSER_START_SECONDS", "30"))


class BrowserUnavailable(RuntimeError):
    """The browser could not be started: the machine's fault, not the page's."""


class Server:
    """`binary explore --port 0`, started; url is what it prints once it listens. As a context
    manager it stops the server on the way out, whatever failed: a server left running would
    hold ctest's output open (it writes to the same standard error) and ctest would wait."""

    def __init__(self, binary, extra_arguments=()):
        self.process = subprocess.Popen([binary, "explore", "--port", "0", *extra_arguments],
                                        stdout=subprocess.PIPE, text=True)
        found = {}

        def read():
            for line in self.process.stdout:
                match = re.search(r"(http://\S+)", line)
                if match and "url" not in found:
                    found["url"] = match.group(1)

        threading.Thread(target=read, daemon=True).start()
        deadline = time.monotonic() + 20
        while "url" not in found:
            if self.process.poll() is not None:
                raise RuntimeError("server exited with %s" % self.process.returncode)
            if time.monotonic() > deadline:
                self.stop()
                raise RuntimeError("server did not start")
            time.sleep(0.02)
        self.url = found["url"]

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.stop()

    def stop(self):
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(5)
            except subprocess.TimeoutExpired:
                self.process.kill()


class Browser:
    """Headless chromium with a fresh profile and a viewport of the given size; close() (or the
    end of a with block) removes both. BrowserUnavailable when it does not start."""

    def __init__(self, width, height):
        # Selenium reaches chromedriver at http://localhost:PORT: without that name (an
        # /etc/hosts with no localhost line) it would retry for 30 s and then fail obscurely.
        try:
            socket.getaddrinfo("localhost", None)
        except OSError as error:
            raise BrowserUnavailable("the name localhost does not resolve (%s), and Selenium "
                                     "reaches chromedriver through it: add '127.0.0.1 "
                                     "localhost' to /etc/hosts" % error) from None
        self.profile = tempfile.mkdtemp(prefix="quaternia-chromium-")
        options = Options()
        options.binary_location = CHROMIUM
        for argument in ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                         "--no-first-run", "--disable-background-networking",
                         "--disable-component-update", "--disable-sync",
                         "--user-data-dir=" + self.profile, "--window-size=%d,%d" % (width, height)]:
            options.add_argument(argument)
        options.set_capability("goog:loggingPrefs", {"browser": "SEVERE"})
        self.driver = self._start(options)
        # The page's viewport exactly (a window's size also counts what headless chromium keeps
        # of its frame).
        self.driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
            "width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})

    def _start(self, options):
        """chromedriver and chromium, within BROWSER_START_SECONDS; else both are killed (they
        run in a process group of their own) and BrowserUnavailable says why."""
        service = Service(CHROMEDRIVER, popen_kw={"start_new_session": True})
        started = {}

        def start():
            try:
                started["driver"] = webdriver.Chrome(service=service, options=options)
            except Exception as error:  # reported below, with the programs' paths
                started["error"] = error

        thread = threading.Thread(target=start, daemon=True)
        thread.start()
        thread.join(BROWSER_START_SECONDS)
        if "driver" in started:
            return started["driver"]
        process = getattr(service, "process", None)
        if process is not None and process.poll() is None:
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except OSError:
                pass
        shutil.rmtree(self.profile, ignore_errors=True)
        reason = started.get("error")
        reason = (str(reason).strip().splitlines() or [type(reason).__name__])[0] if reason \
            else "no answer within %g s" % BROWSER_START_SECONDS
        raise BrowserUnavailable("the browser did not start (chromedriver %s, chromium %s): %s"
                                 % (CHROMEDRIVER, CHROMIUM, reason))

    def uncaught_errors(self):
        """The page's uncaught script errors logged so far."""
        return [entry["message"] for entry in self.driver.get_log("browser")
                if "Uncaught" in entry["message"]]

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.close()

    def close(self):
        try:
            self.driver.quit()
        finally:
            shutil.rmtree(self.profile, ignore_errors=True)


def wait_until(driver, script, timeout=60, *arguments):
    """Waits until the script (a function body returning a value) returns something true."""
    return WebDriverWait(driver, timeout, poll_frequency=0.02).until(
        lambda d: d.execute_script(script, *arguments))


def wait_for_final(driver, timeout=60):
    """Returns once the page shows its final refinement (body[data-state=final])."""
    wait_until(driver, "return document.body.dataset.state === 'final';", timeout)


def shown_image(driver):
    """The bytes of the image the page shows."""
    encoded = driver.execute_async_script("""
        const done = arguments[arguments.length - 1];
        fetch(document.getElementById('view').src)
          .then((response) => response.arrayBuffer())
          .then((buffer) => {
            const bytes = new Uint8Array(buffer);
            let text = '';
            for (const b of bytes) text += String.fromCharCode(b);
            done(btoa(text));
          });""")
    return base64.b64decode(encoded)
