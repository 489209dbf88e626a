"""Connecting to a Dask cluster: the one place where linecontact reaches
``dask.distributed`` (the calculator's batches on a cluster,
:mod:`linecontact.calc.spread`; the table studies' runner in ``tools/`` may share it).

- :func:`check_scheduler_address` reads a ``--scheduler`` value (``tcp://HOST:PORT``,
  ``HOST:PORT``) or refuses it in one line: empty, malformed, a web address;
- :func:`connect` gives a client: to the scheduler at the address once it has
  answered dask's handshake within the connect timeout (nothing listening, an unknown
  host, another kind of server or a dask worker each get their one line), or to a
  local cluster of ``workers`` processes with one thread each, listening on 127.0.0.1
  only, whose workers run without dask's ``MALLOC_TRIM_THRESHOLD_``;
- :func:`linecontact_fingerprint` names the linecontact code a process runs (a worker
  with other code would compute other numbers).

Every refusal is a :class:`ClusterError`, a ValueError whose message is one line and
whose ``exit_code`` is the command's exit status (2 for a bad option, 1 for a fault
during the run). dask and distributed are optional (``pip install
'linecontact[cluster]'``) and imported only here, only when a cluster is asked for.

The table studies' runner (``tools/studies/runner.py``) connects through these too
(:func:`start_client`): one copy of the address rules, the handshake probe and the
local cluster's settings (linecontact never imports ``tools``).
"""
from __future__ import annotations

import contextlib
import hashlib
import logging
from pathlib import Path

__all__ = ["ClusterError", "check_scheduler_address", "check_connect_timeout",
           "check_workers_option", "probe_scheduler", "start_client", "connect",
           "quiet_client_logs", "CLIENT_LOGGERS",
           "require_distributed", "WITHOUT",
           "linecontact_fingerprint", "DEFAULT_CONNECT_TIMEOUT", "DEFAULT_WORKERS",
           "EXTRA"]

#: Seconds for a ``--scheduler`` to answer as a dask scheduler.
DEFAULT_CONNECT_TIMEOUT = 60.0

#: Worker processes of a local cluster when none is said (the reference machine's cores).
DEFAULT_WORKERS = 2

#: The install line that brings the cluster's packages.
EXTRA = "pip install 'linecontact[cluster]'"

#: URL schemes of dask's comms that a ``--scheduler`` address may use.
_SCHEMES = ("tcp", "tls", "ws", "wss", "ucx", "inproc")


class ClusterError(ValueError):
    """A cluster that cannot be used, for a reason the user fixes outside the code; the
    message is one line saying what to do, ``exit_code`` the exit status (2 for a bad
    option, 1 for a fault during the run)."""

    def __init__(self, message, exit_code=2):
        super().__init__(message)
        self.exit_code = exit_code


def require_distributed(option="--scheduler"):
    """Import ``dask.distributed`` or refuse in one line naming the extra to install."""
    try:
        import dask.distributed  # noqa: F401
    except ImportError as exc:
        raise ClusterError(f"{option} needs dask.distributed, which is not installed "
                           f"({exc.name or exc}): {EXTRA}") from None


def _bad_address(scheduler, why):
    return ClusterError(f"--scheduler {scheduler!r}: {why}", exit_code=2)


#: What leaving ``--scheduler`` out does, in its refusals (the study runner: "for a
#: local cluster").
WITHOUT = "to compute in this process"


def check_scheduler_address(scheduler, without=WITHOUT):
    """The address `scheduler` as ``(scheme, host, port)``; a ClusterError (exit 2) with
    one line when it is empty or not a dask scheduler address with a host and a port.
    `without`: what leaving the option out does (said in the line).

    >>> check_scheduler_address("tcp://127.0.0.1:8786")
    ('tcp', '127.0.0.1', 8786)
    >>> check_scheduler_address("10.0.0.5:8786")
    ('tcp', '10.0.0.5', 8786)
    """
    example = f"e.g. tcp://HOST:8786 (leave the option out {without})"
    if not isinstance(scheduler, str) or not scheduler.strip():
        raise _bad_address(scheduler, f"empty: give the address of a running dask "
                                      f"scheduler, {example}")
    text = scheduler.strip()
    scheme, _, rest = text.rpartition("://")
    scheme = scheme.lower() or "tcp"
    if scheme not in _SCHEMES:
        hint = (" (that is a web address: the scheduler's own port is printed by "
                "'dask scheduler' as 'Scheduler at: tcp://...')"
                if scheme in ("http", "https") else "")
        raise _bad_address(scheduler, f"the scheme {scheme!r} is not one of dask's "
                                      f"{', '.join(_SCHEMES)}{hint}; {example}")
    if scheme == "inproc":
        return scheme, rest, None
    host, sep, port = rest.rpartition(":")
    host = host.strip("[]")          # an IPv6 literal, [::1]:8786
    if not sep or not host or not port.isdigit() or not 0 < int(port) < 65536 \
            or any(c in host for c in "/ ?#@"):
        raise _bad_address(scheduler, f"not HOST:PORT after the scheme; {example}")
    return scheme, host, int(port)


def check_connect_timeout(timeout):
    """`timeout` as a float > 0 [s] (None: :data:`DEFAULT_CONNECT_TIMEOUT`), else a
    ClusterError (exit 2)."""
    if timeout is None:
        return DEFAULT_CONNECT_TIMEOUT
    try:
        value = float(timeout)
    except (TypeError, ValueError):
        value = float("nan")
    if not value > 0 or value == float("inf"):
        raise ClusterError(f"--connect-timeout {timeout!r}: give a time in seconds > 0",
                           exit_code=2)
    return value


async def _identify(address, timeout):
    """The scheduler's answer to dask's ``identity`` request at `address`."""
    from distributed.comm import connect as comm_connect
    comm = await comm_connect(address, timeout=timeout)
    try:
        await comm.write({"op": "identity", "reply": True})
        return await comm.read()
    finally:
        comm.abort()


def probe_scheduler(scheduler, timeout, without=WITHOUT):
    """ClusterError (exit 2), within about `timeout` seconds, unless a dask scheduler
    answers at `scheduler`: nothing listening, an unknown host, another server (an
    HTTP port would otherwise hold the client for minutes) or a dask worker each get
    their one line."""
    import asyncio
    import socket
    from concurrent.futures import ThreadPoolExecutor, TimeoutError as FutureTimeout
    scheme, host, port = check_scheduler_address(scheduler, without)
    if scheme in ("tcp", "tls", "ws", "wss"):
        try:
            socket.create_connection((host, port), timeout=timeout).close()
        except ConnectionRefusedError:
            raise _bad_address(scheduler, f"nothing listens on port {port} of {host} "
                                          f"(connection refused): start the scheduler "
                                          f"(dask scheduler --host {host} --port {port}) "
                                          f"or correct the address") from None
        except socket.gaierror as exc:
            raise _bad_address(scheduler, f"unknown host {host!r} ({exc.strerror})") \
                from None
        except (socket.timeout, OSError) as exc:
            raise _bad_address(scheduler, f"no connection to {host}:{port} within "
                                          f"{timeout:g} s ({exc}); is the host up "
                                          f"and the port open?") from None
    if scheme != "tcp":
        return                      # the handshake needs the client's TLS/UCX setup
    address = "tcp://" + scheduler.strip().rpartition("://")[2]   # [::1]:P kept as is
    pool = ThreadPoolExecutor(1)    # its own event loop: safe under a running one
    try:
        reply = pool.submit(asyncio.run, asyncio.wait_for(
            _identify(address, timeout), timeout)).result(timeout + 5)
        why = ""
    except (FutureTimeout, asyncio.TimeoutError, TimeoutError):
        reply, why = None, f"no reply to dask's handshake within {timeout:g} s"
    except Exception as exc:        # noqa: BLE001 - a non-dask peer breaks the
        reply = None                # handshake in many ways; each is named
        why = f"dask's handshake failed: {type(exc).__name__}: {exc}"
    finally:
        pool.shutdown(wait=False)
    kind = reply.get("type") if isinstance(reply, dict) else None
    if kind != "Scheduler":
        what = (f"is a dask {kind}, not the scheduler" if kind else
                f"does not answer as a dask scheduler ({why or 'an unknown reply'}: "
                f"another kind of server, a web port?)")
        raise _bad_address(scheduler, f"{host}:{port} {what}; give the address that "
                                      f"'dask scheduler' prints as 'Scheduler at:'")


def check_workers_option(workers):
    """`workers` as an int >= 1 (None: :data:`DEFAULT_WORKERS`), else a ClusterError."""
    if workers is None:
        return DEFAULT_WORKERS
    try:
        value = int(str(workers).strip())
    except ValueError:
        value = 0
    if value < 1:
        raise ClusterError(f"--workers {workers!r}: give a whole number of worker "
                           f"processes >= 1", exit_code=2)
    return value


def start_client(scheduler=None, workers=None, connect_timeout=None, without=WITHOUT,
                 quiet=True):
    """``(client, cluster)``: a ``distributed.Client`` to the scheduler at `scheduler`
    (probed first, see the module docstring; cluster None), else to a new local
    cluster of `workers` processes (default :data:`DEFAULT_WORKERS`) with one thread
    each on 127.0.0.1 (the cluster: the caller closes both). `quiet`: the local
    workers log only critical messages (not the heartbeats that fail as the cluster
    closes).

    Raises
    ------
    ClusterError
        dask.distributed not installed; a bad address or one that does not answer as
        a dask scheduler within `connect_timeout` seconds (exit 2).
    """
    timeout = check_connect_timeout(connect_timeout)
    if scheduler is not None:
        check_scheduler_address(scheduler, without)     # a typo fails before any import
    require_distributed("--scheduler" if scheduler is not None else "--workers")
    from dask.distributed import Client, LocalCluster
    if scheduler is not None:
        probe_scheduler(scheduler, timeout, without)
        try:
            return Client(scheduler.strip(), timeout=f"{timeout}s"), None
        except (OSError, TimeoutError) as exc:
            raise _bad_address(scheduler, f"no dask client connection within "
                                          f"{timeout:g} s ({exc})") from None
    import dask
    # dask's nannies set MALLOC_TRIM_THRESHOLD_=65536 in the workers' environment
    # (config distributed.nanny.pre-spawn-environ). Setting it switches off glibc's
    # dynamic mmap threshold, so every array above 128 KiB (a 512 x 512 grid is
    # 2 MiB) is mmap'ed and unmapped again: 1.76 million against 64 000 page faults,
    # 13 % more CPU, for one L/R of the paper study at 512 x 512
    # (tools/benchmarks/results/paper_study.txt). None leaves glibc's default (a
    # value the user exported is still passed on: dask prefers os.environ).
    with dask.config.set({"distributed.nanny.pre-spawn-environ."
                          "MALLOC_TRIM_THRESHOLD_": None}):
        cluster = LocalCluster(n_workers=check_workers_option(workers),
                               threads_per_worker=1, processes=True,
                               host="127.0.0.1",          # nothing listens outside
                               dashboard_address=None,    # no dashboard: not needed,
                               # but the scheduler's HTTP server (health, metrics)
                               # runs anyway: on loopback, a free port (not 8787)
                               scheduler_kwargs={"dashboard_address": "127.0.0.1:0"},
                               # the workers' log lines when the cluster closes
                               # (heartbeats to a closed scheduler) say nothing to
                               # the user; a task's failure reaches the caller
                               silence_logs=logging.CRITICAL if quiet else
                               logging.WARNING)
    return Client(cluster), cluster


@contextlib.contextmanager
def connect(scheduler=None, workers=None, connect_timeout=None):
    """:func:`start_client` as a context: the client (and a local cluster) closed at
    the end of the block."""
    client, cluster = start_client(scheduler, workers, connect_timeout)
    try:
        yield client
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


#: Loggers of the client side of distributed whose messages on a lost connection
#: (tracebacks of the reconnection attempts) the callers replace by their own line.
CLIENT_LOGGERS = ("distributed.client", "distributed.comm", "distributed.core",
                  "distributed.batched", "distributed.utils")


def _drop(record):
    return False


@contextlib.contextmanager
def quiet_client_logs(active=True, names=CLIENT_LOGGERS):
    """Drop every record of the loggers `names` inside the block (a filter:
    distributed resets their levels when a client starts); nothing when not `active`.
    After a lost scheduler the client's reconnection task logs its traceback when
    ``client.close()`` cancels it: close the client inside the block. The filter is
    removed at the end in every case (no lasting silence of distributed's logs in a
    notebook)."""
    loggers = [logging.getLogger(n) for n in names] if active else []
    for lg in loggers:
        lg.addFilter(_drop)
    try:
        yield
    finally:
        for lg in loggers:
            lg.removeFilter(_drop)


_FINGERPRINT = []


def linecontact_fingerprint():
    """'linecontact VERSION sha1 HASH' of the Python sources of the linecontact package
    this interpreter imports (relative paths and bytes of every ``*.py``): two processes
    compute the same numbers only if these agree. Computed once per process.

    >>> linecontact_fingerprint().startswith("linecontact ")
    True
    """
    if not _FINGERPRINT:
        import linecontact
        root = Path(linecontact.__file__).resolve().parent
        digest = hashlib.sha1()
        for path in sorted(root.rglob("*.py")):
            rel = path.relative_to(root)
            if rel.parts[0] == "tables" or "__pycache__" in rel.parts:
                continue
            digest.update(rel.as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
        _FINGERPRINT.append(f"linecontact {linecontact.__version__} sha1 "
                            f"{digest.hexdigest()[:12]}")
    return _FINGERPRINT[0]
