"""Optional speech audio: where espeak-ng is installed and --audio-dir is given, each 'say'
also writes a WAV file. It runs in the background and never affects the simulation."""

from __future__ import annotations

import logging
import os
import re
import shutil
import subprocess
from typing import Optional

log = logging.getLogger("kicnp_sim.audio")


class Speaker:
    """Writes <audio_dir>/<robot>-<action id>.wav with espeak-ng, if it is available."""

    def __init__(self, audio_dir: str):
        self.dir = audio_dir
        self.exe = shutil.which("espeak-ng")
        self.procs: list[subprocess.Popen[bytes]] = []
        if self.exe is None:
            log.warning("espeak-ng not found: --audio-dir %s ignored, no WAV files", audio_dir)
        else:
            os.makedirs(audio_dir, exist_ok=True)

    def speak(self, robot: str, action_id: str, text: str) -> Optional[str]:
        """Start writing the WAV; returns its path, or None when there is no espeak-ng."""
        if self.exe is None:
            return None
        self.procs = [p for p in self.procs if p.poll() is None]
        safe = re.sub(r"[^A-Za-z0-9_.-]", "_", f"{robot}-{action_id}")
        path = os.path.join(self.dir, safe + ".wav")
        try:
            self.procs.append(subprocess.Popen([self.exe, "-w", path, "--", text], stdin=subprocess.DEVNULL,
                                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        except OSError as exc:
            log.warning("espeak-ng failed: %s", exc)
            return None
        return path

    def close(self) -> None:
        for p in self.procs:
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                p.kill()
