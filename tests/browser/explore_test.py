"""The explorer in a real browser (Debian's headless chromium): load the page, drag a slider and
see the image change, click the Mandelbrot map and see c change, copy the CLI command and render
it with `quaternia render` to the same picture, byte for byte; key two values of c on the
timeline, play the film and see its frames change, and copy it as a scene file that the library
reads back with both keys.
Usage: python3 explore_test.py --binary build/quaternia [--screenshot docs/explorer.png]"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from harness import (Browser, BrowserUnavailable, Server, shown_image, wait_for_final,
                     wait_until)


def step(text):
    print("browser test: " + text, flush=True)


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def scroll_into_view(driver, element):
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'});", element)
    return element.rect  # x, y, width, height in CSS pixels, after scrolling


def click(driver, element_id):
    element = driver.find_element(By.ID, element_id)
    scroll_into_view(driver, element)
    element.click()


def set_number(driver, element_id, value):
    driver.execute_script("""const box = document.getElementById(arguments[0]);
        box.value = arguments[1];
        box.dispatchEvent(new Event('change'));""", element_id, value)


def timeline(driver, binary, work):
    """Keys c = -1 at 0 s (the basilica, shown) and the rabbit's c at 0.5 s, plays the film at
    8 fps and copies it as a scene file."""
    click(driver, "add-key")
    wait_until(driver, "return document.body.dataset.keys === '[0]';")
    set_number(driver, "timeline-time", 0.5)
    rabbit = driver.find_element(By.CSS_SELECTOR, "#presets button[data-preset=rabbit]")
    scroll_into_view(driver, rabbit)
    rabbit.click()
    wait_until(driver, "return JSON.parse(document.body.dataset.c)[0] !== -1;")
    click(driver, "add-key")
    wait_until(driver, "return document.body.dataset.keys === '[0,0.5]';")
    set_number(driver, "timeline-fps", 8)
    step("keys at 0 s and 0.5 s")

    click(driver, "play")
    wait_until(driver, "return document.body.dataset.play === 'done';", 120)
    frames = driver.execute_script("return window.exploreTiming.playFrames;")
    check([f["frame"] for f in frames] == [1, 2, 3, 4, 5], "frames played: %s" % frames)
    check(len({f["hash"] for f in frames}) == 5, "every frame differs: %s" % frames)
    step("played %d frames, each a different image" % len(frames))

    driver.execute_script("document.body.dataset.scene = '';")
    click(driver, "copy-scene")
    wait_until(driver, "return document.body.dataset.scene;")
    scene = driver.execute_script("return document.body.dataset.scene;")
    check(scene.count("[[animation.keys]]") == 2, scene)
    check(re.search(r"^fps = 8(\.0)?$", scene, re.M), "fps in the scene file")
    keys = scene.split("[[animation.keys]]")[1:]
    check(re.search(r"^time = 0(\.0)?$", keys[0], re.M) and
          re.search(r'^"fractal\.c" = \[-1\.0, 0\.0, 0\.0, 0\.0\]$', keys[0], re.M),
          "the first key: %s" % keys[0])
    check(re.search(r"^time = 0\.5$", keys[1], re.M) and
          re.search(r'^"fractal\.c" = \[-0\.122561', keys[1], re.M),
          "the second key: %s" % keys[1])
    path = os.path.join(work, "film.toml")
    with open(path, "w") as out:
        out.write(scene + "\n")
    subprocess.run([binary, "render", path, "-o", os.path.join(work, "film.png")], check=True,
                   stdout=subprocess.DEVNULL)
    step("copied the film as a scene file with both keys; quaternia render reads it")

    # Drag the second key onto the first (refused: times stay strictly increasing), then to
    # the strip's middle (2 s of 4), then delete it with the Delete key.
    markers = driver.find_elements(By.CSS_SELECTOR, "#track .key")
    scroll_into_view(driver, markers[0])
    ActionChains(driver).click_and_hold(markers[1]).move_to_element(markers[0]).release().perform()
    wait_until(driver, "return document.getElementById('film-info').textContent"
                       ".startsWith('a key is already at 0');")
    check(driver.execute_script("return document.body.dataset.keys;") == "[0,0.5]",
          "a drop on another key is refused")
    track = driver.find_element(By.ID, "track")
    marker = driver.find_elements(By.CSS_SELECTOR, "#track .key")[1]
    ActionChains(driver).click_and_hold(marker).move_to_element(track).release().perform()
    wait_until(driver, "return document.body.dataset.keys === '[0,2]';")
    track.send_keys(Keys.DELETE)
    wait_until(driver, "return document.body.dataset.keys === '[0]';")
    step("dragging refused a drop on a key, moved a key to 2 s; Delete removed it")


def preview_shrinks(driver, server):
    """The preview's size follows its render time (explore.js, adaptPreview): with a budget of
    0.01 ms every preview is too slow, so a drag's frames come smaller than the quarter size, and
    the view still refines to the final size when it stops."""
    driver.get(server.url + "?size=240x160&previewBudget=0.01")
    wait_for_final(driver)
    view = driver.find_element(By.ID, "viewport")
    before = driver.execute_script("return window.exploreTiming.frameInfo.length;")
    actions = ActionChains(driver, duration=0).move_to_element(view).click_and_hold()
    for x in range(12):
        actions.move_by_offset(4, 0).pause(0.1)
    actions.release().perform()
    wait_for_final(driver)
    sizes = [f["size"] for f in
             driver.execute_script("return window.exploreTiming.frameInfo;")[before:]]
    widths = [int(size.split("x")[0]) for size in sizes]
    check(min(widths) < 60, "previews smaller than the quarter size (60x40): %s" % sizes)
    check(sizes[-1] == "240x160", "the still view refined to the final size: %s" % sizes)
    step("previews over budget shrank: %s" % " ".join(sizes))


def explore(server, browser, arguments, work):
    """The page in the browser: every check of the test."""
    driver = browser.driver
    # A small final size keeps the test quick; screenshots fit the window.
    driver.get(server.url + ("" if arguments.screenshot else "?size=240x160"))
    wait_for_final(driver)
    first = shown_image(driver)
    step("page loaded, final image %d bytes" % len(first))

    if arguments.screenshot:
        wait_until(driver, "return document.body.dataset.map === 'ready';")
        driver.save_screenshot(arguments.screenshot)
        step("wrote " + arguments.screenshot)
    else:
        # Certify: the final frame again, its undecided pixels tinted magenta; cleared, the
        # plain picture again.
        click(driver, "certify")
        wait_until(driver, "return document.body.dataset.certify !== undefined;", 120)
        wait_for_final(driver)
        undecided = float(driver.execute_script("return document.body.dataset.certify;"))
        check((shown_image(driver) != first) == (undecided > 0),
              "the tint shows exactly when pixels are undecided (%g)" % undecided)
        check("undecided" in driver.find_element(By.ID, "status").text,
              "the status line gives the undecided fraction")
        click(driver, "certify")
        wait_for_final(driver)
        check(shown_image(driver) == first, "clearing certify shows the plain picture again")
        step("certify tinted %.2f%% of the pixels" % (100 * undecided))

        # Drag the slider of c's i component with the mouse: from its middle to 62% of its
        # width, in 8 moves (offsets are from the element's centre).
        slider = driver.find_element(By.ID, "ctl-fractal_c-1")
        box = scroll_into_view(driver, slider)
        before = driver.execute_script("return document.body.dataset.c;")
        actions = ActionChains(driver).move_to_element(slider).click_and_hold()
        for k in range(1, 9):
            actions.move_to_element_with_offset(slider, int(box["width"] * 0.12 * k / 8), 0)
        actions.release().perform()
        wait_until(driver, "return document.body.dataset.c !== arguments[0];", 60, before)
        wait_for_final(driver)
        dragged = shown_image(driver)
        check(dragged != first, "dragging the slider changes the image")
        step("slider drag changed the image")

        # Click the Mandelbrot map near the rabbit's c. The map shows centre (-0.6, 0), 3.2
        # wide, on a 288 x 216 canvas.
        map_element = driver.find_element(By.ID, "map")
        box = scroll_into_view(driver, map_element)
        scale = 3.2 / 288
        x, y = 144 + (-0.12 + 0.6) / scale, 108 - 0.74 / scale
        offset_x = x * box["width"] / 288 - box["width"] / 2
        offset_y = y * box["height"] / 216 - box["height"] / 2
        ActionChains(driver).move_to_element_with_offset(
            map_element, int(round(offset_x)), int(round(offset_y))).click().perform()
        wait_until(driver, "return JSON.parse(document.body.dataset.c)[2] === 0;")
        c = json.loads(driver.execute_script("return document.body.dataset.c;"))
        check(abs(c[0] + 0.12) < 0.02 and abs(c[1] - 0.74) < 0.02, "c = %s" % c)
        check(re.search(r"c = -0\.1", driver.find_element(By.ID, "c-value").text),
              "the map's label shows the new c")
        wait_for_final(driver)
        shown = shown_image(driver)
        step("map click set c = %s" % c)

        # Copy the CLI command and render it.
        driver.find_element(By.ID, "copy-cli").click()
        wait_until(driver, "return document.body.dataset.cli;")
        command = driver.execute_script("return document.body.dataset.cli;")
        step("copied: " + command)
        check(re.match(r"^quaternia render .* -o quaternia\.png$", command), command)
        output = os.path.join(work, "cli.png")
        shell = re.sub(r"-o quaternia\.png$", '-o "$1"',
                       re.sub(r"^quaternia ", '"$0" ', command))
        subprocess.run(["sh", "-c", shell, arguments.binary, output], check=True)
        with open(output, "rb") as rendered:
            check(rendered.read() == shown,
                  "quaternia render of the copied command gives the PNG the page shows")
        step("quaternia render reproduced the page's image byte for byte")

        # The preset buttons come from the server's list (GET /api/presets).
        names = driver.execute_script(
            "return [...document.querySelectorAll('#presets button')]"
            ".map((b) => b.dataset.preset);")
        check(names[0] == "Start" and "basilica" in names and "rabbit" in names,
              "preset buttons: %s" % names)
        basilica = driver.find_element(By.CSS_SELECTOR, "#presets button[data-preset=basilica]")
        scroll_into_view(driver, basilica)
        basilica.click()
        wait_until(driver, "return document.body.dataset.c === '[-1,0,0,0]';")
        wait_for_final(driver)
        check(shown_image(driver) != shown, "the basilica preset changes the image")
        step("presets %s; basilica set c = -1" % names)
        timeline(driver, arguments.binary, work)
        preview_shrinks(driver, server)
    errors = browser.uncaught_errors()
    check(not errors, "the page threw: %s" % errors)
    print("browser test: passed", flush=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", default="build/quaternia")
    parser.add_argument("--screenshot")
    arguments = parser.parse_args()
    size = (1280, 760) if arguments.screenshot else (900, 560)
    work = tempfile.mkdtemp(prefix="quaternia-browser-")
    try:
        # The server first, inside the with block: whatever fails after it starts (the browser
        # too), it is stopped.
        with Server(arguments.binary) as server, Browser(*size) as browser:
            explore(server, browser, arguments, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    try:
        main()
    except BrowserUnavailable as error:
        print("browser test: FAILED: no browser to test with: %s" % error, file=sys.stderr)
        sys.exit(1)
    except Exception as error:  # one line for ctest's log, then a failing exit
        print("browser test: FAILED: %s" % error, file=sys.stderr)
        sys.exit(1)
