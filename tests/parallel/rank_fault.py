#!/usr/bin/python3
"""A rank that dies (killed as the kernel's out-of-memory killer would, signal 9) stops the whole run of
iga-poisson --solver petsc under mpirun at 3 ranks within seconds, never a hang, exit code non-zero, with a line
naming the rank and the cause (mpirun's: "process rank 1 ... exited on signal 9").
Usage: rank_fault.py IGA_POISSON MPIRUN"""
import os
import subprocess
import sys
import time

exe, mpirun = sys.argv[1], sys.argv[2]
env = dict(os.environ, OMP_NUM_THREADS="1")
# refine 9: 263,169 dofs, several seconds on 3 ranks: rank 1 is killed while the run is under way.
job = subprocess.Popen([mpirun, "-np", "3", "--allow-run-as-root", "--oversubscribe", exe, "--degree", "3", "--refine", "9",
                        "--quiet", "--solver", "petsc", "--vtu", "none", "--json", "none"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)


def rank_of(pid):
    try:
        with open(f"/proc/{pid}/environ", "rb") as f:
            for item in f.read().split(b"\0"):
                if item.startswith(b"OMPI_COMM_WORLD_RANK="):
                    return int(item.split(b"=")[1])
    except OSError:
        pass
    return None


def children(pid):
    out = subprocess.run(["ps", "-o", "pid=", "--ppid", str(pid)], capture_output=True, text=True).stdout.split()
    return [int(p) for p in out]


victim = None
deadline = time.time() + 30
while victim is None and time.time() < deadline and job.poll() is None:
    for pid in children(job.pid):
        if rank_of(pid) == 1 and os.path.basename(os.readlink(f"/proc/{pid}/exe")) == os.path.basename(exe):
            victim = pid
    time.sleep(0.2)
if victim is None:
    job.kill()
    sys.exit("rank 1's process was not found under mpirun")
time.sleep(1.0)  # into the run
killed = time.time()
os.kill(victim, 9)
try:
    out, err = job.communicate(timeout=30)
except subprocess.TimeoutExpired:
    job.kill()
    sys.exit("the run did not stop within 30 s of rank 1's death: a hang")
seconds = time.time() - killed
lines = [l for l in err.splitlines() if "rank 1" in l and "signal 9" in l]
print(f"stopped {seconds:.1f} s after rank 1 was killed, exit code {job.returncode}; {lines}")
if job.returncode == 0:
    sys.exit("exit code 0 after a rank died")
if len(lines) != 1:
    sys.exit("no one line names rank 1 and its signal:\n" + err)
if seconds > 10:
    sys.exit(f"{seconds:.1f} s to stop: not within seconds")
