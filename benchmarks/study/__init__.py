"""Speed against accuracy: every method of computing the scenes, measured in one run."""
