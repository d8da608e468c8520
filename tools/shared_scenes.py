"""Where the large public scenes are: $FREEZERAY_SHARED_SCENES, else ../shared/scenes beside the
repository (the figure scripts of chapters 06 to 08 read Sponza and the ray batches from there,
and skip what needs them when it is absent).

    from shared_scenes import shared_scenes   # after sys.path.insert(0, "<repository>/tools")
"""

from __future__ import annotations

import os
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def shared_scenes() -> Path:
    return Path(os.environ.get("FREEZERAY_SHARED_SCENES", ROOT.parent / "shared" / "scenes"))
