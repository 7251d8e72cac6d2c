#!/usr/bin/env python3
"""Hostile clients of `rtc watch` for benches/hostile.sh (issue 35, defect 7).

    watch_client.py url PORT PID     # a 300 MiB URL; prints the answer's status line
    watch_client.py idle PORT PID    # 3,000 connections that never finish their request;
                                     # prints the watch process's thread count while they are open
"""
import socket
import sys
import time

mode, port, pid = sys.argv[1], int(sys.argv[2]), sys.argv[3]


def threads():
    for line in open(f"/proc/{pid}/status"):
        if line.startswith("Threads:"):
            return int(line.split()[1])
    return -1


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
