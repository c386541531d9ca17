"""Image baseline of the demo: the dam break after 0.1 s, rendered under Xvfb, compared with
Testing/Baselines/demo_dam_break.png by VTK's vtkImageDifference. Threshold: a thresholded error
of at most 10 (VTK's regression-test default), which tolerates anti-aliasing and driver noise but
not particles in other places or other colours.
To refresh the baseline: PARAFLUID_UPDATE_BASELINE=1 ctest -R demo_image"""
import os
import runpy
import shutil
import sys

from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkImagingCore import vtkImageDifference
import pftest

THRESHOLD = 10.0
here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..", "..")
baseline = os.path.join(root, "Testing", "Baselines", "demo_dam_break.png")
out = pftest.scratch_dir()
png = os.path.join(out, "demo.png")

sys.argv = ["demo.py", "--plugin", pftest.plugin_path(), "--outputs", "10", "--interval", "0.01",
            "--result", os.path.join(out, "result.h5part"), "--png", png, "--size", "400", "300"]
runpy.run_path(os.path.join(root, "scripts", "demo.py"), run_name="__main__")

if os.environ.get("PARAFLUID_UPDATE_BASELINE"):
    shutil.copyfile(png, baseline)
    print("baseline updated:", baseline)

def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()

test, base = read(png), read(baseline)
pftest.check(test.GetDimensions() == base.GetDimensions(), "image size %s != baseline %s" % (test.GetDimensions(), base.GetDimensions()))
diff = vtkImageDifference()
diff.SetInputData(test)
diff.SetImageData(base)
diff.Update()
error = diff.GetThresholdedError()
print("demo image: thresholded error %.3f (threshold %.1f)" % (error, THRESHOLD))
if error > THRESHOLD:
    writer = vtkPNGWriter()
    writer.SetFileName(os.path.join(out, "difference.png"))
    writer.SetInputConnection(diff.GetOutputPort())
    writer.Write()
    print("test image and difference kept in", out)
pftest.check(error <= THRESHOLD, "demo render differs from the baseline")
print("demo image: ok")
