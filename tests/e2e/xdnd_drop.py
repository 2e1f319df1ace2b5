#!/usr/bin/python3
"""Drops files on an X11 window the way a file manager does (the XDND protocol, version 5), so
the end-to-end tests reach the viewer's real drop callback through GLFW under Xvfb.
Usage: xdnd_drop.py WINDOW_ID PATH...   Exit status 0 when the window took the drop."""
import sys
import time
import urllib.parse

from Xlib import X, display
from Xlib.protocol import event


def main():
    wid = int(sys.argv[1], 0)
    paths = sys.argv[2:]
    d = display.Display()
    root = d.screen().root
    source = root.create_window(0, 0, 1, 1, 0, X.CopyFromParent)
    target = d.create_resource_object("window", wid)
    atom = lambda name: d.intern_atom(name)
    enter, position, status, drop, finished = (atom(n) for n in ("XdndEnter", "XdndPosition", "XdndStatus", "XdndDrop", "XdndFinished"))
    selection, copy, uri_list = atom("XdndSelection"), atom("XdndActionCopy"), atom("text/uri-list")
    payload = "".join("file://" + urllib.parse.quote(p) + "\r\n" for p in paths).encode()
    source.set_selection_owner(selection, X.CurrentTime)

    def send(kind, data):
        target.send_event(event.ClientMessage(window=target, client_type=kind, data=(32, data + [0] * (5 - len(data)))), event_mask=0)
        d.flush()

    geometry = target.get_geometry()
    origin = target.translate_coords(root, 0, 0)
    x, y = -origin.x + geometry.width // 2, -origin.y + geometry.height // 2
    send(enter, [source.id, 5 << 24, uri_list])
    send(position, [source.id, 0, (x << 16) | y, X.CurrentTime, copy])
    deadline = time.time() + 5
    dropped = False
    while time.time() < deadline:
        if not d.pending_events():
            time.sleep(0.01)
            continue
        e = d.next_event()
        if e.type == X.ClientMessage and e.client_type == status and not dropped:
            if not (e.data[1][1] & 1):
                print("xdnd_drop: the window refused the drop", file=sys.stderr)
                return 1
            send(drop, [source.id, 0, X.CurrentTime])
            dropped = True
        elif e.type == X.SelectionRequest:
            requestor = e.requestor
            requestor.change_property(e.property, e.target, 8, payload)
            requestor.send_event(event.SelectionNotify(time=e.time, requestor=requestor, selection=e.selection,
                                                       target=e.target, property=e.property), event_mask=0)
            d.flush()
        elif e.type == X.ClientMessage and e.client_type == finished:
            return 0
    print("xdnd_drop: no answer from the window", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
