"""Waiting in a running cell for the browser: the kernel's comm messages handled while the cell blocks.

A Jupyter kernel (ipykernel) reads the browser's messages on its shell channel between cells: a
cell that waits for a widget's answer would wait forever. The technique of the jupyter-ui-poll
package (written anew here, no dependency): while the cell waits, read the shell messages
queued for the kernel's main thread ourselves, handle the comm messages (``comm_open``,
``comm_msg``, ``comm_close``: widget traits, custom messages) at once with the kernel's own
handlers, and hand every other message (an ``execute_request`` of the next cell, say) back to
the kernel's own receive callback, which queues it behind the running cell as if it had just
arrived, in order.

Where the shell messages wait for the main thread, by ipykernel version:

- ipykernel 7 (kernel subshells): a thread reads the shell socket and forwards each message
  for the main shell over an inproc PAIR socket, read on the main thread by a ZMQStream
  (``kernel.shell_channel_thread.manager._shell_channel_to_main.to_stream``); its callback
  schedules ``kernel.shell_main``, which waits for the running cell's lock.
- ipykernel 6 (and 7 without subshells): the shell socket's own ZMQStream
  (``kernel.shell_stream``) on the main thread; in 6 its callback puts the message on the
  kernel's queue (``schedule_dispatch``), processed after the running cell.

Each pump reads until the socket has nothing more (EAGAIN), so no message is left behind
unsignalled for the stream once the cell returns. Elsewhere (plain Python, a terminal IPython,
marimo, an unknown kernel) ``BlockingUnavailable`` says so at once instead of hanging.
"""

from __future__ import annotations

import sys
import threading
from typing import Any, Callable

COMM_TYPES = frozenset({"comm_open", "comm_msg", "comm_close"})


class BlockingUnavailable(RuntimeError):
    """This Python cannot wait for the browser inside a cell (no Jupyter kernel that can be pumped)."""


def _kernel() -> Any:
    ipython = sys.modules.get("IPython")
    get_ipython = getattr(ipython, "get_ipython", None) if ipython is not None else None
    shell = get_ipython() if get_ipython is not None else None
    if shell is None:
        raise BlockingUnavailable("no IPython kernel runs this code (plain Python, a script, marimo)")
    kernel = getattr(shell, "kernel", None)
    if kernel is None:
        raise BlockingUnavailable(f"{type(shell).__name__} has no Jupyter kernel (a terminal IPython?): nothing shows the widget")
    return kernel


class KernelPump:
    """Handles the browser's comm messages while a cell blocks (see the module's docstring)."""

    def __init__(self) -> None:
        kernel = _kernel()
        self.kernel = kernel
        self.session = getattr(kernel, "session", None)
        handlers = getattr(kernel, "shell_handlers", None)
        if self.session is None or not isinstance(handlers, dict) or not all(t in handlers for t in COMM_TYPES):
            raise BlockingUnavailable(f"the kernel ({type(kernel).__module__}.{type(kernel).__name__}) is not an ipykernel with comms")
        self.handlers = handlers
        self.stream: Any = None
        # With subshells (ipykernel 7) a cell may run in a subshell's thread: the main thread
        # then handles the comms itself, and waiting is only sleeping.
        self.passive = False
        channel = getattr(kernel, "shell_channel_thread", None)
        if channel is not None:
            parent = getattr(channel, "parent_thread", None)
            if parent is not None and threading.current_thread() is not parent:
                self.passive = True
                return
            manager = getattr(channel, "manager", None)
            pair = getattr(manager, "_shell_channel_to_main", None)
            self.stream = getattr(pair, "to_stream", None)
        else:
            if threading.current_thread() is not threading.main_thread():
                raise BlockingUnavailable("this code runs outside the kernel's main thread")
            self.stream = getattr(kernel, "shell_stream", None)
        if self.stream is None or getattr(self.stream, "socket", None) is None or getattr(self.stream, "_recv_callback", None) is None:
            version = getattr(sys.modules.get("ipykernel"), "__version__", "?")
            raise BlockingUnavailable(f"this ipykernel ({version}) keeps its shell messages where tissue_sheet cannot read them")
        self.reply_stream = getattr(kernel, "shell_stream", None)

    def pump(self, timeout: float) -> int:
        """Waits up to ``timeout`` s for shell messages and handles every one queued; returns how many."""
        if self.passive:
            threading.Event().wait(timeout)
            return 0
        import zmq

        socket = self.stream.socket
        copy = bool(getattr(self.stream, "_recv_copy", False))
        if not socket.poll(max(0, int(timeout * 1000)), zmq.POLLIN):
            return 0
        count = 0
        while True:
            try:
                frames = socket.recv_multipart(zmq.NOBLOCK, copy=copy)
            except zmq.Again:
                return count
            count += 1
            self._handle(frames, copy)

    def _handle(self, frames: list, copy: bool) -> None:
        handler: Callable | None = None
        try:
            idents, parts = self.session.feed_identities(frames, copy=copy)
            # The header alone first (no signature check: a message handed back is checked, and
            # recorded against replay, once, by the kernel itself).
            header = parts[1] if copy else parts[1].bytes
            msg_type = self.session.unpack(header).get("msg_type")
            if msg_type in COMM_TYPES:
                handler = self.handlers.get(msg_type)
                msg = self.session.deserialize(parts, content=True, copy=copy)
        except Exception:
            handler = None
        if handler is None:
            # Not a comm (or not readable here): the kernel's own callback queues it behind this cell.
            self.stream._run_callback(self.stream._recv_callback, frames)
            return
        try:
            handler(self.reply_stream, idents, msg)
        except Exception:
            log = getattr(self.kernel, "log", None)
            if log is not None:
                log.error("tissue_sheet: a comm message failed while waiting for the browser", exc_info=True)
