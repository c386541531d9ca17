"""Image baseline of the demo: the dam break after 0.1 s, rendered under Xvfb, compared with
Testing/SPH/Baselines/demo_dam_break.png by VTK's vtkImageDifference. Threshold: a thresholded error
of at most 10 (VTK's regression-test default), which tolerates anti-aliasing and driver noise but
not particles in other places or other colours.
To refresh the baseline: PARAFLUID_UPDATE_BASELINE=1 ctest -R demo_image"""
import os
import runpy
import sys

import pftest

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..", "..")
out = pftest.scratch_dir()
png = os.path.join(out, "demo.png")

sys.argv = ["demo.py", "--plugin", pftest.plugin_path(), "--outputs", "10", "--interval", "0.01",
            "--result", os.path.join(out, "result.h5part"), "--png", png, "--size", "400", "300"]
runpy.run_path(os.path.join(root, "scripts", "demo.py"), run_name="__main__")

pftest.compare_with_baseline(png, "demo_dam_break.png")
print("demo image: ok")
