#!/usr/bin/env python3
"""Hostile clients of `rtc watch` for benches/hostile.sh (issue 35, defect 7).

    watch_client.py url PORT PID     # a 300 MiB URL; prints the answer's status line
    watch_client.py idle PORT PID    # 3,000 connections that never finish their request;
                                     # prints the watch process's thread count while they are open
    watch_client.py texture PORT PID TEXTURE  # rewrites the 1024x1024 PNG TEXTURE 40 times,
                                     # each after the last render's final frame; prints the
                                     # process's resident memory after the 10th and the 40th
"""
import os
import socket
import sys
import time

mode, port, pid = sys.argv[1], int(sys.argv[2]), sys.argv[3]


def status(field):
    for line in open(f"/proc/{pid}/status"):
        if line.startswith(field):
            return int(line.split()[1])
    return -1


def threads():
    return status("Threads:")


def final_frames(sock):
    """Yields once per `final` frame event of the event stream on `sock`."""
    buf = b""
    while True:
        data = sock.recv(65536)
        if not data:
            return
        buf += data
        while b"\n\n" in buf:
            event, buf = buf.split(b"\n\n", 1)
            if b"event: frame" in event and b'"stage":"final"' in event:
                yield


def png(path, shade):
    """A 1024x1024 grey PNG of the given shade, written as editors save (a rename)."""
    import struct
    import zlib
    w = h = 1024
    row = b"\x00" + bytes([shade, shade, shade]) * w
    raw = zlib.compress(row * h, 1)
    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    body = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    body += chunk(b"IDAT", raw) + chunk(b"IEND", b"")
    with open(path + ".tmp", "wb") as f:
        f.write(body)
    os.replace(path + ".tmp", path)


if mode == "url":
    s = socket.create_connection(("127.0.0.1", port))
    chunk = b"a" * (1 << 20)
    try:
        s.sendall(b"GET /")
        for _ in range(300):
            s.sendall(chunk)
        s.sendall(b" HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % port)
    except OSError:
        pass  # the server stopped reading (and closed): its answer is already here
    try:
        answer = s.recv(200).split(b"\r\n")[0].decode()
    except OSError as e:
        answer = f"({e})"
    print(answer or "(closed)", end="")
elif mode == "texture":
    texture = sys.argv[4]
    s = socket.create_connection(("127.0.0.1", port))
    s.sendall(b"GET /events HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % port)
    frames = final_frames(s)
    next(frames)
    rss = {}
    for n in range(1, 41):
        png(texture, 50 + 4 * n)
        next(frames)
        if n in (10, 40):
            rss[n] = status("VmRSS:") // 1024
    print(f"RSS {rss[10]} MiB after 10 edits, {rss[40]} MiB after 40", end="")
else:
    conns = []
    for _ in range(3000):
        c = socket.create_connection(("127.0.0.1", port))
        try:
            c.sendall(b"GET / HTTP/1.1\r\n")
        except OSError:
            pass  # answered 503 and closed already
        conns.append(c)
    time.sleep(2)
    print(f"{threads()} threads with 3,000 open", end="")
