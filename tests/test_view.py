"""``artipg view``: the viewer serves a page that a real headless browser (Debian's
chromium) draws, and moving a joint slider in that browser moves the served joint.

The browser is driven through the Chrome DevTools protocol (a websocket, no extra
package); the tests skip when viser or chromium is missing.
"""

from __future__ import annotations

import io
import json
import shutil
import socket
import subprocess
import time
import urllib.request

import numpy as np
import pytest

import artipg

viser = pytest.importorskip("viser")
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _wait(pred, timeout: float, what: str):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        out = pred()
        if out:
            return out
        time.sleep(0.2)
    raise AssertionError(f"timed out waiting for {what}")


class Browser:
    """Headless chromium on ``url``, driven over the DevTools websocket."""

    def __init__(self, url: str, profile, size: tuple = (960, 720)):
        from websockets.sync.client import connect

        port = _free_port()
        self.proc = subprocess.Popen(
            [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             "--enable-unsafe-swiftshader", f"--window-size={size[0]},{size[1]}", f"--user-data-dir={profile}",
             f"--remote-debugging-port={port}", url],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

        def page():
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=2) as r:
                    pages = [t for t in json.load(r) if t.get("type") == "page"]
            except OSError:
                return None
            return pages[0]["webSocketDebuggerUrl"] if pages else None

        self.ws = connect(_wait(page, 30, "chromium's DevTools endpoint"), max_size=None, open_timeout=10)
        self.n = 0

    def call(self, method: str, **params) -> dict:
        self.n += 1
        self.ws.send(json.dumps({"id": self.n, "method": method, "params": params}))
        while True:
            msg = json.loads(self.ws.recv(timeout=30))
            if msg.get("id") == self.n:
                if "error" in msg:
                    raise RuntimeError(f"{method}: {msg['error']}")
                return msg.get("result", {})

    def screenshot(self) -> np.ndarray:
        import base64

        from PIL import Image

        data = base64.b64decode(self.call("Page.captureScreenshot", format="png")["data"])
        return np.asarray(Image.open(io.BytesIO(data)).convert("RGB"))

    def evaluate(self, js: str):
        return self.call("Runtime.evaluate", expression=js, returnByValue=True).get("result", {}).get("value")

    def key(self, key: str, code: int) -> None:
        for kind in ("rawKeyDown", "keyUp"):
            self.call("Input.dispatchKeyEvent", type=kind, key=key, code=key, windowsVirtualKeyCode=code)

    def close(self) -> None:
        try:
            self.ws.close()
        finally:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    from artipg.export import export_object

    root = tmp_path_factory.mktemp("view")
    for seed in (0, 1):
        export_object(artipg.generate("storage_furniture", seed), root / "storage_furniture" / str(seed),
                      n_points=1024)
    return root


@pytest.fixture()
def viewer(folder):
    from artipg.appearance.viewer import Viewer

    v = Viewer(folder, host="127.0.0.1", port=_free_port())
    yield v
    v.server.stop()


def test_viewer_loads_every_object_and_moves_links(viewer, folder):
    assert len(viewer.folders) == 2 and viewer.q and all(v == 0.0 for v in viewer.q.values())
    name = next(iter(viewer.sliders))
    child = next(j.child for j in viewer.urdf.robot.joints if j.name == name)
    def pose():
        return np.concatenate([viewer.frames[child].position, viewer.frames[child].wxyz])

    before = pose()
    viewer.sliders[name].value = viewer.sliders[name].max  # as the browser's slider does
    assert viewer.q[name] == pytest.approx(viewer.sliders[name].max)
    assert np.abs(pose() - before).max() > 1e-3  # the link moved
    for mode in viewer.mode.options:  # every colour mode recolours without error
        viewer.mode.value = mode
    for box, kind in ((viewer.show_points, "points"), (viewer.show_grasps, "grasps"), (viewer.show_boxes, "boxes")):
        assert viewer._layers[kind] and not any(h.visible for h in viewer._layers[kind])
        box.value = True
        assert all(h.visible for h in viewer._layers[kind])
    viewer.picker.value = viewer.picker.options[1]
    assert viewer.folder == viewer.folders[1]


def test_view_command_fails_clearly_on_bad_paths(tmp_path):
    from typer.testing import CliRunner

    from artipg.cli import app

    r = CliRunner().invoke(app, ["view", str(tmp_path / "missing")])
    assert r.exit_code != 0 and "does not exist" in r.output
    r = CliRunner().invoke(app, ["view", str(tmp_path)])
    assert r.exit_code != 0 and "no object folder" in r.output


@pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (apt-get install chromium)")
def test_headless_browser_shows_the_object_and_its_slider_moves_a_joint(viewer, tmp_path):
    browser = Browser(viewer.url, tmp_path / "profile")
    try:
        _wait(lambda: viewer.server.get_clients(), 60, "the browser to connect")
        _wait(lambda: browser.evaluate("document.querySelectorAll('[role=slider]').length")
              == len(viewer.sliders), 60, "the joint sliders")
        time.sleep(3.0)  # meshes arrive and the canvas draws
        img = browser.screenshot()
        assert img.shape[0] > 100 and img.std() > 10, "blank page"
        # the object is drawn: many pixels of the 3D canvas differ from its background
        canvas = img[:, : img.shape[1] * 2 // 3]
        bg = np.median(canvas.reshape(-1, 3), axis=0)
        assert (np.abs(canvas.astype(int) - bg).sum(axis=2) > 30).mean() > 0.02
        name = next(iter(viewer.sliders))
        assert viewer.q[name] == 0.0
        browser.evaluate("document.querySelectorAll('[role=slider]')[0].focus()")
        for _ in range(5):
            browser.key("ArrowRight", 39)
        _wait(lambda: viewer.q[name] != 0.0, 20, "the slider to move the joint")
        assert viewer.q[name] > 0.0
    finally:
        browser.close()
