"""Explorer timings in headless chromium: time to first frame at 640x360 (a quarter-resolution
frame, 160x90 with one sample, arrives first) and frames shown per second while dragging to
orbit, with the median size and server time of the frames shown while dragging. Medians of
several runs. --preset NAME or a scene file starts the explorer from that scene (the algebras'
rows of docs/benchmarks.md).
Usage: python3 explore_bench.py --binary build/quaternia [--runs 5] [--size 640x360]
       [--preset NAME] [scene.toml]"""
import argparse
import json
import statistics

from selenium.webdriver.common.action_chains import ActionChains
from selenium.common.exceptions import TimeoutException
from selenium.webdriver.common.by import By

from harness import Browser, Server, wait_for_final, wait_until


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", default="build/quaternia")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--preset")
    parser.add_argument("--size", default="640x360", help="the final frame's size, WxH")
    parser.add_argument("scene", nargs="?")
    arguments = parser.parse_args()
    extra = ([arguments.scene] if arguments.scene else []) + (
        ["--preset", arguments.preset] if arguments.preset else [])
    with Server(arguments.binary, extra) as server, Browser(980, 400) as browser:
        driver = browser.driver
        first_frame, first_frame_script, first_render, fps = [], [], [], []
        drag_sizes, drag_render_ms = [], []
        for _ in range(arguments.runs):
            driver.get(server.url + "?size=" + arguments.size)
            wait_until(driver, "return window.exploreTiming && "
                               "window.exploreTiming.firstFrameMs !== null;")
            timing = driver.execute_script("return window.exploreTiming;")
            first_frame.append(timing["firstFrameSinceNavigationMs"])
            first_frame_script.append(timing["firstFrameMs"])
            first_render.append(timing["firstRenderMs"])
            # The final frame where it comes within 10 s; a slow algebra's full-size frames
            # (minutes at 1920x1080) are left to the drag, which cancels them.
            try:
                wait_for_final(driver, 10)
            except TimeoutException:
                pass

            # Drag across the view for 3 s, a mouse event every 16 ms (60 Hz), as one action
            # sequence so that the driver's round trips do not set the pace.
            view = driver.find_element(By.ID, "viewport")
            width = view.rect["width"]
            before = driver.execute_script("return window.exploreTiming.frames.length;")
            actions = ActionChains(driver, duration=0)
            actions.move_to_element_with_offset(view, int(100 - width / 2), 0).click_and_hold()
            x = 100
            for _ in range(int(3.0 / 0.016)):
                x = 100 + ((x - 100 + 3) % 400)
                actions.move_to_element_with_offset(view, int(x - width / 2), 0).pause(0.016)
            start = driver.execute_script("return performance.now();")
            actions.perform()
            seconds = (driver.execute_script("return performance.now();") - start) / 1000
            frames = driver.execute_script("return window.exploreTiming.frameInfo;")[before:]
            ActionChains(driver).release().perform()
            fps.append(len(frames) / seconds)
            drag_sizes += [f["size"] for f in frames]
            drag_render_ms += [f["renderMs"] for f in frames]
        print(json.dumps({
            "size": arguments.size, "runs": arguments.runs,
            "first_frame_ms_since_navigation": statistics.median(first_frame),
            "first_frame_ms_since_script": statistics.median(first_frame_script),
            "first_frame_server_render_ms": statistics.median(first_render),
            "drag_frames_per_second": statistics.median(fps),
            "drag_frame_size": statistics.median_low(drag_sizes) if drag_sizes else None,
            "drag_frame_server_render_ms": statistics.median(drag_render_ms)
            if drag_render_ms else None,
        }))


if __name__ == "__main__":
    main()
