"""`lfd gantry` against `lfd gantry-sim`, which the CTest fixture started on
127.0.0.1 (port LFD_GANTRY_PORT) with an emergency stop armed for the first
move: homing, the e-stop mid-move (one error line, the axis stopped, the
fault reported until reset), recovery, a move; the refusals (unreachable
port, taken port, unknown fault mode, a description without its port); the
coaxial lamp on a coil (`lfd gantry lamp on|off --coil N`); and the README's
Python examples (gantry, lamp). The
other refusals and faults are the C++ tests' (Testing/Cxx)."""
import os
import re
import socket
import subprocess
import sys

import lfd

LFD = os.environ["LFD_EXECUTABLE"]
PORT = int(os.environ["LFD_GANTRY_PORT"])
DEVICE = f"gantry 127.0.0.1:{PORT}: "
failures = []


def check(condition, what, value):
    print(("ok   " if condition else "FAIL ") + f"{what}: {value}")
    if not condition:
        failures.append(what)


def gantry(*words, port=PORT):
    """Runs `lfd gantry WORDS --port P` with short moves (120 degree/s,
    480 degree/s^2)."""
    return subprocess.run([LFD, "gantry", *words, "--port", str(port), "--velocity", "120",
                           "--acceleration", "480", "--timeout", "0.3"],
                          capture_output=True, text=True, timeout=60)


def expect(result, code, stdout, stderr, what):
    check(result.returncode == code and result.stdout == stdout and result.stderr == stderr,
          what, f"exit {result.returncode}, stdout {result.stdout!r}, stderr {result.stderr!r}")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


expect(gantry("status"), 0, DEVICE + "at 37.500 deg, disabled, not homed, stopped\n", "",
       "status at power-up")
expect(gantry("home"), 0, DEVICE + "at 0.000 deg, ready, homed, in position\n", "", "homed")

# The fixture armed an emergency stop for the first move: half-way.
expect(gantry("move", "30"), 1, "",
       "lfd: error: " + DEVICE + "drive fault 2 (emergency stop) during the move to 30 deg\n",
       "e-stop mid-move: one error line")
status = gantry("status")
match = re.fullmatch(re.escape(DEVICE) + r"at (\S+) deg, disabled, homed, stopped, "
                     r"drive fault 2 \(emergency stop\)\n", status.stdout)
check(status.returncode == 0 and match and 5.0 < float(match.group(1)) < 25.0,
      "the axis stopped between 5 and 25 deg, fault 2 reported", status.stdout.strip())
expect(gantry("move", "30"), 1, "",
       "lfd: error: " + DEVICE + "drive fault 2 (emergency stop): reset it first\n",
       "no move while the fault is there")
reset = gantry("reset")
check(reset.returncode == 0 and reset.stdout.endswith(", disabled, homed, stopped\n"),
      "reset", reset.stdout.strip())
# The same gantry through its description; a description without its port.
description = os.path.join(os.environ.get("LFD_TEMP_DIR", "/tmp"), "gantry_cli.json")
with open(description, "w") as f:
    f.write('{ "format": "lfd-gantry", "version": 1, "address": "127.0.0.1", "port": %d, '
            '"velocity": 120, "acceleration": 480 }' % PORT)
moved = subprocess.run([LFD, "gantry", "move", "30", "--config", description],
                       capture_output=True, text=True, timeout=60)
expect(moved, 0, DEVICE + "at 30.000 deg, ready, homed, in position\n", "",
       "moved to 30 deg after the reset (--config)")
with open(description, "w") as f:
    f.write('{ "format": "lfd-gantry", "version": 1, "address": "127.0.0.1" }')
expect(subprocess.run([LFD, "gantry", "status", "--config", description], capture_output=True,
                      text=True, timeout=60), 1, "",
       f'lfd: error: {description}: field "port": missing\n', "a description without its port")
stop = gantry("stop")
check(stop.returncode == 0 and stop.stdout == DEVICE + "at 30.000 deg, ready, homed, in position\n",
      "a quick stop at rest changes nothing", stop.stdout.strip())

# Refusals: one line each, exit 1.
port = free_port()
expect(gantry("status", port=port), 1, "",
       f"lfd: error: gantry 127.0.0.1:{port}: cannot connect: Connection refused (3 attempts)\n",
       "nothing listens: ECONNREFUSED")
taken = subprocess.run([LFD, "gantry-sim", "--port", str(PORT)], capture_output=True, text=True,
                       timeout=60)
expect(taken, 1, "",
       f"lfd: error: gantry simulator 127.0.0.1:{PORT}: cannot listen: Address already in use\n",
       "a simulator on a taken port")
bad_fault = subprocess.run([LFD, "gantry-sim", "--fault", "meteor"], capture_output=True,
                           text=True, timeout=60)
check(bad_fault.returncode == 2 and "--fault" in bad_fault.stderr,
      "an unknown fault mode is a command-line error", bad_fault.stderr.strip())

# The coaxial lamp on coil 2 of the controller, as `lfd capture
# --coaxial-coil 2` switches it: read back after each switch.
LAMP = f"coaxial lamp 127.0.0.1:{PORT} coil "
expect(gantry("lamp", "on", "--coil", "2"), 0, LAMP + "2: on (read back)\n", "", "lamp on")
expect(gantry("lamp", "off", "--coil", "2"), 0, LAMP + "2: off (read back)\n", "", "lamp off")
expect(gantry("lamp", "on", "--coil", "8"), 1, "",
       "lfd: error: " + LAMP + "8: the controller refused the request: Illegal data address "
       "while switching it on\n", "a coil the controller lacks")

# The README's Python example.
simulator = lfd.vtkGantrySimulator()
check(simulator.Start(), "simulator serving in this process", simulator.GetBoundPort())
device = lfd.vtkModbusGantry()
device.SetAddress("127.0.0.1")
device.SetPort(simulator.GetBoundPort())
device.SetVelocity(120.0)
device.SetAcceleration(480.0)
moved = device.Connect() and device.Enable() and device.Home() and device.MoveTo(90.0)
check(moved and device.GetActualAngle() == 90.0, "Python: homed, moved to 90 deg",
      device.GetActualAngle())
# The README's lamp example (The coaxial lamp on a Modbus coil).
lamp = lfd.vtkModbusLight()
lamp.SetName("coaxial lamp")
lamp.SetAddress("127.0.0.1")
lamp.SetPort(simulator.GetBoundPort())
lamp.SetCoil(2)
on = lamp.Apply(lfd.vtkLightField.COAXIAL) and simulator.GetCoil(2)
off = lamp.Apply(lfd.vtkLightField.FLOOD) and not simulator.GetCoil(2)
lamp.Off()
check(on and off, "Python: the lamp on coil 2 on for Coaxial, off for Flood", (on, off))
simulator.Stop()

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
