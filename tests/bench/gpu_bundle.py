#!/usr/bin/env python3
"""Bundles the Release viewer and benchmarks with the shared libraries they load, for a GPU
machine that has none of Debian's packages (docs/platform.md, "On a GPU again").

    python3 tests/bench/gpu_bundle.py [BUILD=build] [OUT=.gpu]

writes OUT/build/{app,tests/bench}/... and OUT/lib. There, with libglvnd's EGL installed:

    LD_LIBRARY_PATH=$PWD/OUT/lib NPR_DATA_DIR=$PWD bash tests/bench/gpu_check.sh OUT/build 30 IMAGES

The real libraries OpenImageIO pulls in come to 355 MB, over what such a call carries; most
serve formats the check never reads (video, DICOM, OpenVDB, camera raw, HEIF, JPEG 2000) or
colour management it never asks for. Those are replaced by stubs defining only the symbols
the kept libraries import, under the versions they ask for; every stub function returns a
pointer to zeroed memory, because OpenImageIO asks each library for its version string when it
lists its plugins. glibc and the GL libraries are left to the machine.
"""
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, 'build'))
OUT = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, '.gpu'))
BINARIES = ['app/npr-viewer', 'tests/bench/bench_frames', 'tests/bench/bench_animation', 'tests/bench/bench_scene']
STUBBED = re.compile(r'lib(opencv_\w+|dcm\w+|oflog|ofstd|xml2|avcodec|avformat|avutil|swscale|heif|openjp2|openvdb|raw_r|OpenColorIO)\.so')
SYSTEM = re.compile(r'(libc|libm|libpthread|libdl|librt|libresolv|ld-linux-x86-64|libEGL|libGL|libGLX|libOpenGL|libGLdispatch|libGLESv2)\.so')
SEARCH = ['/lib/x86_64-linux-gnu', '/usr/lib/x86_64-linux-gnu']


def needed(path):
    dump = subprocess.run(['objdump', '-p', path], capture_output=True, text=True, check=True).stdout
    return re.findall(r'NEEDED\s+(\S+)', dump)


def locate(name):
    for d in SEARCH:
        if os.path.exists(os.path.join(d, name)):
            return os.path.join(d, name)
    sys.exit('gpu_bundle: %s is not installed here' % name)


def dynamic_symbols(path):
    """(name, version, type, size, defined) for each dynamic symbol of a library."""
    table = subprocess.run(['readelf', '-W', '--dyn-syms', path], capture_output=True, text=True, check=True).stdout
    for line in table.splitlines():
        f = line.split()
        if len(f) < 8 or not f[0].rstrip(':').isdigit():
            continue
        name, _, version = f[7].partition('@')
        yield name, version.lstrip('@'), f[3], int(f[2], 0), f[6] not in ('UND', 'ABS')


def stub(name, lib_dir, wanted):
    """A library of the same soname defining what the kept libraries import from `name`."""
    asm = ['.text', '.Lempty_result: lea .Lzeroes(%rip), %rax', ' ret', '.bss', '.balign 64', '.Lzeroes: .zero 4096']
    versions, done = {}, set()
    for sym, _, kind, size, defined in dynamic_symbols(locate(name)):
        if not defined or not sym or sym in done or sym not in wanted:
            continue
        done.add(sym)
        for v in wanted[sym]:
            versions.setdefault(v, []).append(sym)
        q = '"%s"' % sym
        if kind in ('FUNC', 'IFUNC', 'NOTYPE'):
            asm += ['.text', '.globl ' + q, '.type %s,@function' % q, '%s: jmp .Lempty_result' % q]
        elif kind in ('OBJECT', 'TLS'):
            section = '.section .tbss,"awT",@nobits' if kind == 'TLS' else '.data'
            type_ = '@tls_object' if kind == 'TLS' else '@object'
            n = max(size, 1)
            asm += [section, '.balign 16', '.globl ' + q, '.type %s,%s' % (q, type_), '.size %s,%d' % (q, n), '%s: .zero %d' % (q, n)]
    source, script = os.path.join(OUT, 'stub.s'), os.path.join(OUT, 'stub.map')
    with open(source, 'w') as f:
        f.write('\n'.join(asm) + '\n')
    with open(script, 'w') as f:
        f.write(''.join('%s { global: %s; };\n' % (v, '; '.join('"%s"' % x for x in xs)) for v, xs in versions.items()) or '{ global: *; };\n')
    subprocess.run(['gcc', '-shared', '-fPIC', '-Wa,--noexecstack', '-Wl,--version-script=' + script, '-Wl,-soname,' + name,
                    '-o', os.path.join(lib_dir, name), source], check=True)
    os.remove(source)
    os.remove(script)


def main():
    lib_dir = os.path.join(OUT, 'lib')
    shutil.rmtree(OUT, ignore_errors=True)
    os.makedirs(lib_dir)
    binaries = []
    for b in BINARIES:
        src = os.path.join(BUILD, b)
        if not os.path.exists(src):
            sys.exit('gpu_bundle: no %s (build the Release configuration first)' % src)
        dst = os.path.join(OUT, 'build', b)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copy(src, dst)
        binaries.append(dst)
    seen, stubbed, todo = set(), [], [n for b in binaries for n in needed(b)]
    while todo:
        n = todo.pop()
        if n in seen or SYSTEM.match(n):
            continue
        seen.add(n)
        if STUBBED.match(n):
            stubbed.append(n)
            continue
        path = locate(n)
        shutil.copy(os.path.realpath(path), os.path.join(lib_dir, n))
        todo += needed(path)
    wanted = {}  # symbol -> the versions the kept libraries and binaries ask for
    for path in binaries + [os.path.join(lib_dir, n) for n in os.listdir(lib_dir)]:
        for sym, version, _, _, defined in dynamic_symbols(path):
            if not defined:
                wanted.setdefault(sym, set()).update([version] if version else [])
    for n in sorted(stubbed):
        stub(n, lib_dir, wanted)
    size = sum(os.path.getsize(os.path.join(lib_dir, n)) for n in os.listdir(lib_dir))
    print('gpu_bundle: %d libraries, %d of them stubs, %.0f MB, in %s' % (len(seen), len(stubbed), size / 1e6, lib_dir))


if __name__ == '__main__':
    main()
