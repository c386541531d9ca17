"""What the pysph peer scripts share (benchmark-only helpers; nothing of pysph is built into ParaFluid):
loading one of Debian python3-pysph's examples as a module, and timing its steps."""
import importlib.util
import os
import time

import pysph


def load_example(relative_path, name):
    """The example at pysph/examples/<relative_path>, imported as module `name` (its globals can then
    be set before its application is created)."""
    path = os.path.join(os.path.dirname(pysph.__file__), "examples", relative_path)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class StepClock:
    """Mixed into an example's application: call clock_step(solver) from post_step. Keeps the fluid's
    particle array, the step count and the wall clock from the first step to the last, so the
    setup (pysph compiles its equations first) is not counted."""

    first_step_clock = None
    last_step_clock = None
    steps = 0
    fluid = None

    def clock_step(self, solver):
        if self.first_step_clock is None:
            self.first_step_clock = time.perf_counter()
            self.fluid = [pa for pa in solver.particles if pa.name == "fluid"][0]
        self.steps = solver.count
        self.last_step_clock = time.perf_counter()

    def wall_seconds(self):
        return self.last_step_clock - self.first_step_clock
