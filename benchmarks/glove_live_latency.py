#!/usr/bin/env python3
"""Latency of the glove live without a browser: from a 'G' reply written into a pseudo-terminal
(socat's pair standing in for the glove) to its server-sent event at a plain HTTP client of
`pmdplan glove stream --serve`, and to pmdplan's read of it (the event's read_ms). Prints the
median, 95th percentile and maximum; asserts nothing. The browser's share is measured by
viewer/test/live_glove_browser_test.mjs.

    python3 benchmarks/glove_live_latency.py build/pmdplan [--frames 500] [--rate 100]
"""
import argparse
import json
import os
import re
import socket
import subprocess
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GLOVE = os.path.join(ROOT, 'data', 'glove')


def sample_frames():
    lines = [line for line in open(os.path.join(GLOVE, 'synthetic_operator_sample.csv')) if line.strip() and not line.startswith('#')]
    return [[int(cell) for cell in line.split(',')[1:]] for line in lines[1:]]


def percentile(values, share):
    return values[min(len(values) - 1, int(share * len(values)))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('cli')
    parser.add_argument('--frames', type=int, default=500)
    parser.add_argument('--rate', type=float, default=100.0)
    o = parser.parse_args()
    frames = sample_frames()
    with tempfile.TemporaryDirectory() as work:
        glove, host = os.path.join(work, 'glove'), os.path.join(work, 'host')
        socat = subprocess.Popen(['socat', '-d', '-d', f'pty,raw,echo=0,link={glove}', f'pty,raw,echo=0,link={host}'],
                                 stderr=subprocess.DEVNULL)
        stream = None
        try:
            deadline = time.time() + 10
            while not (os.path.exists(glove) and os.path.exists(host)):
                if time.time() > deadline:
                    raise SystemExit('socat made no pseudo-terminal pair')
                time.sleep(0.01)
            stream = subprocess.Popen([o.cli, 'glove', 'stream', '--device', host, '--poll-rate', '0', '--timeout', '30',
                                       '--calibration', os.path.join(GLOVE, 'synthetic_operator_sample.calibration.yaml'),
                                       '--serve', '0', '--out', os.path.join(work, 'viewer')],
                                      stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
            port = None
            for line in stream.stdout:
                match = re.search(r'127\.0\.0\.1:(\d+)/', line)
                port = int(match.group(1)) if match else port
                if 'streaming from' in line:
                    break
            if port is None:
                raise SystemExit('pmdplan glove stream did not serve')
            client = socket.create_connection(('127.0.0.1', port), timeout=10)
            client.sendall(b'GET /events HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n')
            written = {}
            line_fd = os.open(glove, os.O_RDWR | os.O_NOCTTY)

            def write_frames():
                for i in range(o.frames):
                    written[i] = time.time() * 1000
                    os.write(line_fd, bytes([0x47] + frames[i % len(frames)] + [0]))
                    time.sleep(1 / o.rate)

            writer = threading.Thread(target=write_frames)
            writer.start()
            received, to_client, to_read = b'', [], []
            while len(to_client) < o.frames:
                received += client.recv(65536)
                while b'\n\n' in received:
                    event, received = received.split(b'\n\n', 1)
                    now = time.time() * 1000
                    for field in event.split(b'\n'):
                        if field.startswith(b'data: {"frame"'):
                            data = json.loads(field[6:])
                            to_client.append(now - written[data['frame']])
                            to_read.append(data['read_ms'] - written[data['frame']])
            writer.join()
            os.close(line_fd)
        finally:
            socat.terminate()
            socat.wait()
            if stream:
                stream.wait(timeout=10)
    to_client.sort()
    to_read.sort()
    print(f'glove live latency over {o.frames} frames at {o.rate:g} Hz: serial write -> event at the client: median '
          f'{percentile(to_client, 0.5):.2f} ms, p95 {percentile(to_client, 0.95):.2f} ms, max {to_client[-1]:.2f} ms; '
          f'serial write -> pmdplan read: median {percentile(to_read, 0.5):.2f} ms, p95 {percentile(to_read, 0.95):.2f} ms')


if __name__ == '__main__':
    main()
