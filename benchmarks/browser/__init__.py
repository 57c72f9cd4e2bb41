"""Measurements in Chromium: the canvas's frame rate against a bare viser page, and its floor."""
