"""Lecture exports that need no server and no internet: offline HTML, images, GIF/MP4, paper figures."""
