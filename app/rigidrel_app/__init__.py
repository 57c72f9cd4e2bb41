"""rigidrel's front ends: the viser app, the command line, exports, notebook helpers.

Layers, each importing only those below it (an import-linter contract checks this):

* :mod:`~rigidrel_app.cli` (the ``rigidrel`` command);
* :mod:`~rigidrel_app.live` (the viser server), :mod:`~rigidrel_app.notebook`;
* :mod:`~rigidrel_app.export` (offline HTML, images, GIF/MP4, the paper's figures);
* :mod:`~rigidrel_app.backends` (plotly, viser, raster: they only draw sampled coordinates);
* :mod:`~rigidrel_app.view` (pure: what a scene looks like, as sampled coordinates).

Importing ``rigidrel_app`` is cheap: viser and plotly are imported only by the modules
that draw. The app computes no physics; it asks :mod:`rigidrel_core` for sampled arrays.
The benchmarks (``rigidrel bench`` among them) live in the checkout's ``benchmarks/``, not here.
"""
