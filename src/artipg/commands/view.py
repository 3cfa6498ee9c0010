"""``artipg view``: an interactive viewer of exported objects in the browser (viser)."""

from __future__ import annotations

from pathlib import Path

import typer

from artipg.commands import fail


def register(app: typer.Typer) -> None:
    @app.command()
    def view(
        path: Path = typer.Argument(..., help="An object folder (with mobility.urdf) or a folder of many."),
        host: str = typer.Option("127.0.0.1", "--host", help="Interface to serve on (0.0.0.0 for remote "
                                                           "machines; or forward the port over ssh)."),
        port: int = typer.Option(8080, "--port", help="Port to serve on."),
    ) -> None:
        """Serve an interactive viewer (joint sliders, colour modes, grasps, NPCS boxes); prints its URL."""
        if not path.exists():
            fail(f"{path} does not exist")
        if not 0 < port < 65536:
            fail(f"--port must be in 1..65535, got {port}")
        try:
            import viser  # noqa: F401
        except ImportError:
            fail("the viewer needs viser: pip install 'artipg[view]'")
        from artipg.appearance.viewer import Viewer, object_folders

        if not object_folders(path):
            fail(f"no object folder (with mobility.urdf) at or below {path}")
        try:
            viewer = Viewer(path, host=host, port=port)
        except OSError as e:
            fail(f"cannot serve on {host}:{port}: {e.strerror or e}")
        print(f"artipg view: {len(viewer.folders)} object(s) at {viewer.url}  (Ctrl-C to stop)", flush=True)
        viewer.server.sleep_forever()
