# SPDX-License-Identifier: Apache-2.0
"""rays-compare: the Active Rays tracker beside OpenCV trackers on sequences with ground truth (tools/rays-compare)."""
