"""rigidrel's front ends: the viser app, the command line, exports.

Importing ``app`` is cheap: viser and plotly are imported only by the modules that draw.
The app computes no physics; it asks :mod:`rigidrel_core` for sampled arrays.
"""
