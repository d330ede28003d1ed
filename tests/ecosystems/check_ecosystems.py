#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Builds the core the way each firmware ecosystem's tool would, from the manifest the repository
ships for it: the files it lists, its include paths and its flags. None of PlatformIO, ESP-IDF or
Zephyr runs here, so this script reads each manifest as its tool does (the CMake ones are run by
cmake -P with the tool's commands replaced by recorders) and compiles what it found with
arm-none-eabi-g++ for Cortex-M4, with the tool's usual flags and the manifest's in the order the tool
gives them; the Arduino library is built by Debian's arduino-builder itself, with a Cortex-M4 test
platform (arduino_platform/). Each build is linked into a program that calls ts_open and ts_render
on a golden blob (linked, not run: the check is of what the manifests build).

Usage: check_ecosystems.py MODE ROOT WORK [TRIPACK]
  platformio    library.json: build.srcDir, srcFilter, includeDir, flags, unflags
  arduino       ports/arduino/assemble.sh (needs TRIPACK), then arduino-builder on the example sketch
  esp-idf       firmware_core/idf_component.yml, and firmware_core/CMakeLists.txt as ESP-IDF runs it
  zephyr        zephyr/module.yml, zephyr/Kconfig (its defaults against config.h's), zephyr/CMakeLists.txt
  cxx-standard  every source as -std=gnu++11 and -std=gnu++14: the first error is config.h's #error
Exit 0 on success, 1 naming the manifest and what is wrong, 77 when a needed program is missing."""

import concurrent.futures
import glob
import json
import os
import re
import shutil
import subprocess
import sys

CXX = "arm-none-eabi-g++"
CPU = ["-mcpu=cortex-m4", "-mthumb"]
SOURCE_EXTENSIONS = (".c", ".cc", ".cpp", ".cxx", ".S")
# A firmware's configuration of the core, as a project would pass it to each tool (README): one
# format, one method, RGB blobs of one mesh. It is also what keeps each build to seconds.
USER_DEFINES = ["-DTS_PIXEL_FORMATS=0x08", "-DTS_METHODS=0x1", "-DTS_COLOR_SPACES=0x2", "-DTS_LAYERED=0"]
GOLDEN_BLOB = "tests/golden/rgb-bilinear.bin"  # RGB, bilinear: within USER_DEFINES' configuration
CPP17_ERROR = "tristream's core needs C++17"
# config.h's settings that it derives from the compiler, not defaults a build system sets.
DERIVED_SETTINGS = {"TS_USE_SSE2", "TS_USE_INT128"}


class Failure(Exception):
    pass


def fail(where, message):
    raise Failure(f"{where}: {message}")


def run(cmd, cwd=None):
    return subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def core_sources(root):
    src = os.path.join(root, "firmware_core", "src")
    return sorted(os.path.join(src, f) for f in os.listdir(src) if f.endswith(SOURCE_EXTENSIONS))


def core_version(root):
    with open(os.path.join(root, "firmware_core/include/tristream/version.h")) as f:
        return re.search(r'#define TRISTREAM_VERSION "([^"]+)"', f.read()).group(1)


def check_sources(where, listed, expected_names):
    """Every listed file exists, and the listed files are the core's sources (by file name), once each."""
    for path in listed:
        if not os.path.isfile(path):
            fail(where, f"lists {path}, which does not exist")
    names = [os.path.basename(p) for p in listed]
    missing = sorted(set(expected_names) - set(names))
    extra = sorted(set(names) - set(expected_names))
    twice = sorted({n for n in names if names.count(n) > 1})
    if missing:
        fail(where, f"does not build {', '.join(missing)} (firmware_core/src has it)")
    if extra:
        fail(where, f"builds {', '.join(extra)}, which is not a source of firmware_core/src")
    if twice:
        fail(where, f"builds {', '.join(twice)} more than once")


def check_dirs(where, dirs):
    for d in dirs:
        if not os.path.isdir(d):
            fail(where, f"include directory {d} does not exist")


def check_version(where, got, root):
    want = core_version(root)
    if got != want:
        fail(where, f"version {got!r}, but tristream/version.h says {want!r}")


def compile_all(where, sources, flags, work):
    """Compiles each source into WORK (two at a time); returns the objects, or fails with the first error."""
    os.makedirs(work, exist_ok=True)

    def one(i_src):
        i, src = i_src
        obj = os.path.join(work, f"{i}_{os.path.basename(src)}.o")
        cmd = [CXX] + flags + ["-c", src, "-o", obj]
        result = run(cmd)
        return obj, cmd, result

    objects = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for obj, cmd, result in pool.map(one, enumerate(sources)):
            if result.returncode != 0:
                fail(where, f"compiling failed:\n{' '.join(cmd)}\n{result.stdout}")
            objects.append(obj)
    return objects


def write_program(root, work):
    """A C program that renders the golden blob through the C API, and the blob as a C array."""
    with open(os.path.join(root, GOLDEN_BLOB), "rb") as f:
        blob = f.read()
    rows = ",\n".join(", ".join(str(b) for b in blob[i:i + 24]) for i in range(0, len(blob), 24))
    path = os.path.join(work, "program.c")
    with open(path, "w") as f:
        f.write(f"""#include "tristream/tristream.h"

static const uint8_t blob_bytes[{len(blob)}] __attribute__((aligned(4))) = {{
{rows}
}};
static uint8_t band[2048 * 16 * 2];
static uint8_t workspace[64 * 1024];
volatile unsigned long pixels;

static void send_band(void* context, const ts_tile* tile) {{
  (void)context;
  pixels += (unsigned long)(tile->rect.x1 - tile->rect.x0) * (unsigned long)(tile->rect.y1 - tile->rect.y0);
}}

int main(void) {{
  ts_blob blob;
  ts_params params = TS_PARAMS_INIT;
  params.format = TS_RGB565_BE;
  params.tile_height = 16;
  if (ts_open(blob_bytes, sizeof blob_bytes, &blob, (uint32_t*)0) != TS_OK) return 1;
  if (ts_render(&blob, &params, band, sizeof band, workspace, sizeof workspace, send_band, (void*)0) != TS_OK) return 2;
  return 0;
}}
""")
    return path


def link_program(where, root, objects, include_dirs, defines, work):
    """Compiles the program as C89 against the public include directories alone, and links it."""
    program = write_program(root, work)
    obj = os.path.join(work, "program.o")
    cmd = (["arm-none-eabi-gcc", "-std=c89", "-Wall", "-Wextra", "-Werror", "-Os"] + CPU + defines +
           [f"-I{d}" for d in include_dirs] + ["-c", program, "-o", obj])
    result = run(cmd)
    if result.returncode != 0:
        fail(where, f"the program does not compile against the manifest's include directories:\n{result.stdout}")
    elf = os.path.join(work, "program.elf")
    cmd = [CXX] + CPU + ["-Os", "-Wl,--gc-sections", "--specs=nano.specs", "--specs=nosys.specs", obj] + objects + \
        ["-o", elf]
    result = run(cmd)
    if result.returncode != 0:
        fail(where, f"linking failed:\n{' '.join(cmd)}\n{result.stdout}")
    return elf


def first_error(output):
    for line in output.splitlines():
        if "error:" in line:
            return line
    return None


def expect_cpp17_error(where, cmd):
    result = run(cmd)
    error = first_error(result.stdout)
    if result.returncode == 0 or error is None or CPP17_ERROR not in error or "config.h" not in error:
        fail(where, f"expected config.h's '{CPP17_ERROR}' as the first error of\n{' '.join(cmd)}\ngot:\n"
             f"{result.stdout[:2000]}")


# --- PlatformIO -------------------------------------------------------------------------------------

def platformio_sources(src_dir, src_filter):
    """PlatformIO's source filter: +<pattern> adds, -<pattern> removes, in order; a pattern is a glob
    relative to srcDir, and a directory it matches stands for every file under it."""
    if isinstance(src_filter, list):
        src_filter = " ".join(src_filter)
    chosen = set()
    for sign, pattern in re.findall(r"([+-])<([^>]*)>", src_filter):
        matched = set()
        for path in glob.glob(os.path.join(src_dir, pattern)):
            if os.path.isdir(path):
                for d, _, files in os.walk(path):
                    matched.update(os.path.join(d, f) for f in files)
            else:
                matched.add(path)
        chosen = chosen | matched if sign == "+" else chosen - matched
    return sorted(p for p in chosen if p.endswith(SOURCE_EXTENSIONS))


def check_platformio(root, work, _tripack):
    where = "library.json"
    with open(os.path.join(root, where)) as f:
        lib = json.load(f)
    check_version(where, lib.get("version"), root)
    build = lib.get("build", {})
    src_dir = os.path.join(root, build.get("srcDir", "src"))
    include_dir = os.path.join(root, build.get("includeDir", "include"))
    # PlatformIO's default filter for a library: everything but VCS folders, examples and tests.
    default_filter = "+<*> -<.git/> -<.svn/> -<example/> -<examples/> -<test/> -<tests/>"
    sources = platformio_sources(src_dir, build.get("srcFilter", default_filter))
    check_sources(where, sources, [os.path.basename(p) for p in core_sources(root)])
    check_dirs(where, [include_dir])
    as_list = lambda v: v.split() if isinstance(v, str) else list(v or [])
    lib_flags, unflags = as_list(build.get("flags")), as_list(build.get("unflags"))
    if not any(re.fullmatch(r"-std=(gnu|c)\+\+(17|1z|2a|20|2b|23)", f) for f in lib_flags):
        fail(where, "build.flags sets no C++17 (the toolchain's default standard may be older)")
    # A C++ compile is $CXX -c $CXXFLAGS $CCFLAGS (SCons): the library's -std goes to CXXFLAGS; the
    # project's (gnu++11 in Arduino-ESP32 2.x) is modelled in CCFLAGS, after it, where a platform
    # may put it, so only the library's unflags remove it. The project's build_flags give the
    # core's configuration.
    project_cxx = ["-fno-exceptions", "-fno-rtti"]
    project_cc = ["-Os", "-ffunction-sections", "-fdata-sections", "-Wall", "-std=gnu++11"]
    flags = ([f for f in project_cxx if f not in unflags] + lib_flags +
             [f for f in project_cc if f not in unflags] + USER_DEFINES)
    project = project_cxx + project_cc
    # The library's own build sees its include directory and its srcDir.
    include_flags = [f"-I{include_dir}", f"-I{src_dir}"]
    expect_cpp17_error(f"{where} (the project's flags without the library's)",
                       [CXX] + CPU + project + include_flags + ["-fsyntax-only", sources[0]])
    objects = compile_all(where, sources, CPU + flags + include_flags, os.path.join(work, "objects"))
    link_program(where, root, objects, [include_dir], USER_DEFINES, work)
    print(f"platformio: library.json builds {len(sources)} sources from {build.get('srcDir')} "
          f"({' '.join(lib_flags)}, without {' '.join(unflags)}) and links")


# --- Arduino ----------------------------------------------------------------------------------------

def check_arduino(root, work, tripack):
    where = "ports/arduino"
    builder = shutil.which("arduino-builder")
    if builder is None:
        print("arduino: SKIPPED: arduino-builder is not installed (tools/install-deps.sh ecosystems)")
        sys.exit(77)
    if not tripack:
        fail(where, "needs the path of tripack")
    shutil.rmtree(work, ignore_errors=True)
    out = os.path.join(work, "release")
    result = run(["bash", os.path.join(root, "ports/arduino/assemble.sh"), out, tripack])
    if result.returncode != 0:
        fail(where, f"assemble.sh failed:\n{result.stdout}")
    lib = os.path.join(out, "tristream")
    props = dict(line.split("=", 1) for line in open(os.path.join(lib, "library.properties")).read().splitlines()
                 if "=" in line and not line.startswith("#"))
    for field in ("name", "version", "author", "maintainer", "sentence", "paragraph", "category", "architectures"):
        if not props.get(field):
            fail(f"{where}/library.properties", f"has no {field}")
    check_version(f"{where}/library.properties", props["version"], root)
    version = props["version"]
    if not os.path.isfile(os.path.join(out, f"tristream-{version}.zip")):
        fail(where, f"assemble.sh wrote no tristream-{version}.zip")
    # The layout: only src/ is compiled (recursively) and on the include path.
    src = os.path.join(lib, "src")
    sources = sorted(os.path.join(d, f) for d, _, files in os.walk(src) for f in files if f.endswith(SOURCE_EXTENSIONS))
    check_sources(f"{where} (the assembled src/)", sources, [os.path.basename(p) for p in core_sources(root)])
    for d, _, files in os.walk(os.path.join(root, "firmware_core/include")):
        for f in files:
            rel = os.path.relpath(os.path.join(d, f), os.path.join(root, "firmware_core/include"))
            if not os.path.isfile(os.path.join(src, rel)):
                fail(where, f"the assembled src/ lacks the public header {rel}")
    # The builder finds the library that provides an #include by the headers at the top of src/:
    # there only tristream.h, so that no private header (shader.h, ...) shadows another library's.
    top = sorted(f for f in os.listdir(src) if os.path.isfile(os.path.join(src, f)))
    if top != ["tristream.h"]:
        fail(where, f"the top of the assembled src/ holds {top}, expected tristream.h alone")
    examples = os.path.join(lib, "examples")
    sketches = sorted(os.listdir(examples))
    for name in sketches:
        if not os.path.isfile(os.path.join(examples, name, name + ".ino")):
            fail(where, f"examples/{name} has no {name}.ino (the builder's sketch layout)")
    if not sketches:
        fail(where, "has no example sketch")
    # The library in a libraries folder, built by arduino-builder for each example sketch on a
    # platform whose C++ defaults to gnu++11 (as Arduino-ESP32 2.x): as shipped, the sketch's
    # build_opt.h gives -std=gnu++17; without it the build must stop at config.h's #error; and
    # without it but with compiler.cpp.extra_flags=-std=gnu++17 (what platform.local.txt sets) it
    # must build again.
    hardware = os.path.join(os.path.dirname(os.path.abspath(__file__)), "arduino_platform")
    # Debian's arduino-builder keeps its own platform.txt (the ctags recipe of sketch preprocessing)
    # in share/arduino-builder beside its bin/; the IDE passes that folder as a hardware folder.
    builtin = os.path.join(os.path.dirname(os.path.dirname(os.path.realpath(builder))), "share", "arduino-builder")
    libraries = os.path.join(work, "libraries")
    os.makedirs(libraries)
    os.symlink(lib, os.path.join(libraries, "tristream"))
    tools = os.path.join(work, "tools")
    os.makedirs(tools)
    expected = sorted(os.path.basename(p) for p in core_sources(root))
    for name in sketches:
        def build(sketch_dir, extra, tag):
            path = os.path.join(work, f"build-{name}-{tag}")
            os.makedirs(path)
            cmd = [builder, "-compile", "-hardware", builtin, "-hardware", hardware, "-tools", tools,
                   "-libraries", libraries, "-fqbn", "tristream:cortexm4:m4", "-build-path", path,
                   "-warnings", "all", f"-prefs=build.extra_flags={' '.join(USER_DEFINES)}"] + extra + \
                [os.path.join(sketch_dir, name + ".ino")]
            return cmd, run(cmd), path

        def expect_built(cmd, result, path, how):
            if result.returncode != 0:
                fail(where, f"arduino-builder failed on examples/{name} {how}:\n{' '.join(cmd)}\n"
                     f"{result.stdout[-6000:]}")
            if not os.path.isfile(os.path.join(path, name + ".ino.elf")):
                fail(where, f"arduino-builder wrote no {name}.ino.elf {how}")
            built = sorted(f[:-2] for d, _, files in os.walk(os.path.join(path, "libraries")) for f in files
                           if f.endswith(".o"))
            if built != expected:
                fail(where, f"arduino-builder compiled {built} of the library {how}, expected {expected}")

        expect_built(*build(os.path.join(examples, name), [], "as shipped"), "as shipped (its build_opt.h)")
        bare = os.path.join(work, "without-build-opt", name)
        shutil.copytree(os.path.join(examples, name), bare)
        if os.path.exists(os.path.join(bare, "build_opt.h")):
            os.remove(os.path.join(bare, "build_opt.h"))
        cmd, result, _ = build(bare, [], "gnu++11")
        error = first_error(result.stdout)
        if result.returncode == 0 or error is None or CPP17_ERROR not in error:
            fail(where, f"without build_opt.h, as gnu++11, arduino-builder should stop at config.h's #error, got:\n"
                 f"{result.stdout[-3000:]}")
        expect_built(*build(bare, ["-prefs=compiler.cpp.extra_flags=-std=gnu++17"], "extra-flags"),
                     "with compiler.cpp.extra_flags=-std=gnu++17")
        print(f"arduino: arduino-builder built examples/{name} with the library's {len(expected)} sources "
              f"(with its build_opt.h: linked; without, as gnu++11: config.h's #error; with "
              f"compiler.cpp.extra_flags=-std=gnu++17: linked)")


# --- ESP-IDF ----------------------------------------------------------------------------------------

def cmake_record(where, script, work):
    """Runs a CMake script that writes 'key<TAB>value' lines to WORK/record.txt; returns them in order."""
    record = os.path.join(work, "record.txt")
    if os.path.exists(record):
        os.remove(record)
    path = os.path.join(work, "stub.cmake")
    with open(path, "w") as f:
        f.write(script.replace("@RECORD@", record))
    result = run(["cmake", "-P", path])
    if result.returncode != 0:
        fail(where, f"cmake -P failed:\n{result.stdout}")
    lines = open(record).read().splitlines() if os.path.exists(record) else []
    return [tuple(line.split("\t", 1)) for line in lines]


def cmake_list(value):
    return [v for v in value.split(";") if v]


def check_esp_idf(root, work, _tripack):
    import yaml  # python3-yaml
    os.makedirs(work, exist_ok=True)
    component = os.path.join(root, "firmware_core")
    where = "firmware_core/idf_component.yml"
    with open(os.path.join(root, where)) as f:
        manifest = yaml.safe_load(f)
    check_version(where, str(manifest.get("version")), root)
    if "idf" not in (manifest.get("dependencies") or {}):
        fail(where, "names no ESP-IDF version under dependencies: idf")
    where = "firmware_core/CMakeLists.txt (ESP-IDF)"
    # ESP-IDF reads a component's CMakeLists.txt twice. First, to collect requirements, as a script
    # with idf_component_register a macro that returns from the file (ESP_PLATFORM not yet set);
    # then in the build, with ESP_PLATFORM set and the component's library named COMPONENT_LIB.
    # Anything else the file calls is CMake's own, or missing (an error), as in a script.
    register = f"""
  set(multi SRCS SRC_DIRS EXCLUDE_SRCS INCLUDE_DIRS PRIV_INCLUDE_DIRS REQUIRES PRIV_REQUIRES LDFRAGMENTS
            EMBED_FILES EMBED_TXTFILES REQUIRED_IDF_TARGETS)
  cmake_parse_arguments(A "WHOLE_ARCHIVE" "KCONFIG;KCONFIG_PROJBUILD" "${{multi}}" ${{ARGN}})
  if(A_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "idf_component_register: unknown arguments ${{A_UNPARSED_ARGUMENTS}}")
  endif()
  foreach(key SRCS SRC_DIRS EXCLUDE_SRCS INCLUDE_DIRS PRIV_INCLUDE_DIRS)
    file(APPEND "@RECORD@" "${{key}}\t${{A_${{key}}}}\n")
  endforeach()"""
    early = cmake_record(f"{where}, requirements pass", f"""
set(CMAKE_BUILD_EARLY_EXPANSION 1)
set(COMPONENT_DIR "{component}")
macro(idf_component_register){register}
  return()
endmacro()
include("{component}/CMakeLists.txt")
""", work)
    if not any(key == "SRCS" for key, _ in early):
        fail(f"{where}, requirements pass", "does not call idf_component_register")
    records = cmake_record(where, f"""
set(ESP_PLATFORM 1)
set(COMPONENT_LIB __idf_tristream)
set(COMPONENT_DIR "{component}")
function(idf_component_register){register}
endfunction()
function(target_compile_options target scope)
  file(APPEND "@RECORD@" "options\t${{target}};${{scope}};${{ARGN}}\n")
endfunction()
function(target_compile_definitions target scope)
  file(APPEND "@RECORD@" "definitions\t${{target}};${{scope}};${{ARGN}}\n")
endfunction()
include("{component}/CMakeLists.txt")
""", work)
    if [r for r in records if r[0] not in ("options", "definitions")] != early:
        fail(where, "registers other files or folders in the requirements pass than in the build")
    got = {}
    options, definitions = [], []
    for key, value in records:
        if key == "options" or key == "definitions":
            target, scope, *rest = cmake_list(value)
            if target != "__idf_tristream":
                fail(where, f"sets {key} of {target}, not of ${{COMPONENT_LIB}}")
            (options if key == "options" else definitions).extend(rest)
        else:
            got[key] = cmake_list(value)
    if "SRCS" not in got:
        fail(where, "does not call idf_component_register when ESP_PLATFORM is set")
    resolve = lambda p: p if os.path.isabs(p) else os.path.normpath(os.path.join(component, p))
    sources = [resolve(p) for p in got["SRCS"]]
    for d in got.get("SRC_DIRS", []):
        sources += sorted(glob.glob(os.path.join(resolve(d), "*.c")) + glob.glob(os.path.join(resolve(d), "*.cpp")) +
                          glob.glob(os.path.join(resolve(d), "*.S")))
    excluded = {resolve(p) for p in got.get("EXCLUDE_SRCS", [])}
    sources = [s for s in sources if s not in excluded]
    check_sources(where, sources, [os.path.basename(p) for p in core_sources(root)])
    include_dirs = [resolve(d) for d in got.get("INCLUDE_DIRS", [])]
    private_dirs = [resolve(d) for d in got.get("PRIV_INCLUDE_DIRS", [])]
    check_dirs(where, include_dirs + private_dirs)
    if not any(o.startswith("-std=") for o in options):
        fail(where, "sets no C++ standard for the component (ESP-IDF's global one may be older than C++17)")
    # ESP-IDF's global options come first and the component's target options after them: a global
    # -std=gnu++11 (where a project or an old ESP-IDF has one) loses to the component's.
    global_flags = ["-Og", "-ffunction-sections", "-fdata-sections", "-Wall", "-Werror=all", "-std=gnu++11",
                    "-fno-exceptions", "-fno-rtti"]
    include_flags = [f"-I{d}" for d in include_dirs + private_dirs]
    expect_cpp17_error(f"{where} (ESP-IDF's global flags without the component's)",
                       [CXX] + CPU + global_flags + include_flags + ["-fsyntax-only", sources[0]])
    flags = CPU + global_flags + include_flags + options + [f"-D{d}" for d in definitions] + USER_DEFINES
    objects = compile_all(where, sources, flags, os.path.join(work, "objects"))
    link_program(where, root, objects, include_dirs, USER_DEFINES, work)
    print(f"esp-idf: the component registers {len(sources)} sources, INCLUDE_DIRS {' '.join(got['INCLUDE_DIRS'])}, "
          f"options {' '.join(options)}; built and linked")


# --- Zephyr -----------------------------------------------------------------------------------------

def config_h_defaults(root):
    """TS_* -> default value of every setting of config.h; the settings it derives from the compiler apart."""
    with open(os.path.join(root, "firmware_core/include/tristream/config.h")) as f:
        text = f.read()
    settings = re.findall(r"#ifndef (TS_\w+)\n", text)
    defaults = dict(re.findall(r"#ifndef (TS_\w+)\n#define \1 (\S+)\n#endif", text))
    for name in settings:
        if name not in defaults and name not in DERIVED_SETTINGS:
            raise Failure(f"config.h: {name} has no plain default; check_ecosystems.py does not know it")
    return {k: int(v, 0) for k, v in defaults.items()}


def parse_kconfig(path):
    """config NAME blocks: type, default, depends on, range (the subset zephyr/Kconfig uses)."""
    symbols, current = {}, None
    for raw in open(path):
        line = raw.split("#", 1)[0].rstrip()
        m = re.match(r"^config\s+(\w+)$", line)
        if m:
            current = symbols.setdefault(m.group(1), {"depends": []})
            continue
        s = line.strip()
        if current is None or not s or raw.startswith(("if", "endif", "menu", "endmenu")):
            if raw.startswith(("if", "endif", "menu", "endmenu")):
                current = None
            continue
        m = re.match(r"^(bool|int|hex|string)\b", s)
        if m:
            current["type"] = m.group(1)
        elif s.startswith("default "):
            current.setdefault("default", s.split(None, 1)[1])
        elif s.startswith("depends on "):
            current["depends"].append(s[len("depends on "):])
        elif s.startswith("range "):
            current["range"] = s.split()[1:3]
    return symbols


def kconfig_value(symbol):
    value = symbol.get("default")
    if symbol["type"] == "bool":
        return 1 if value == "y" else 0
    return int(value, 0)


def zephyr_run(root, work, configs):
    """zephyr/CMakeLists.txt with CONFIG_* as Zephyr's .config import gives them; returns what it asked for."""
    module = os.path.join(root, "zephyr")
    sets = "\n".join(f'set({k} "{v}")' for k, v in configs.items())
    commands = ["zephyr_library", "zephyr_library_named", "zephyr_library_sources", "zephyr_include_directories",
                "zephyr_library_include_directories", "zephyr_compile_definitions",
                "zephyr_library_compile_definitions", "zephyr_library_compile_options", "zephyr_compile_options"]
    stubs = "\n".join(f'function({c})\n  file(APPEND "@RECORD@" "{c}\\t${{ARGN}}\\n")\nendfunction()' for c in commands)
    os.makedirs(work, exist_ok=True)
    records = cmake_record("zephyr/CMakeLists.txt", f'{sets}\nset(ZEPHYR_CURRENT_MODULE_DIR "{root}")\n{stubs}\n'
                           f'include("{module}/CMakeLists.txt")\n', work)
    got = {}
    for key, value in records:
        got.setdefault(key, []).extend(cmake_list(value))
    return got


def zephyr_configs(kconfig, overrides):
    """CONFIG_* values: y for a bool that is on (absent when off), decimal ints, hex as 0x..."""
    configs = {"CONFIG_TRISTREAM": "y"}
    for name, symbol in kconfig.items():
        if name == "TRISTREAM":
            continue
        value = overrides.get(name, kconfig_value(symbol))
        if symbol["type"] == "bool":
            if value:
                configs[f"CONFIG_{name}"] = "y"
        elif symbol["type"] == "hex":
            configs[f"CONFIG_{name}"] = hex(value)
        else:
            configs[f"CONFIG_{name}"] = str(value)
    return configs


def check_zephyr(root, work, _tripack):
    import yaml  # python3-yaml
    where = "zephyr/module.yml"
    with open(os.path.join(root, where)) as f:
        module = yaml.safe_load(f)
    build = module.get("build") or {}
    cmake_dir = os.path.join(root, build.get("cmake", ""))
    kconfig_path = os.path.join(root, build.get("kconfig", ""))
    if not build.get("cmake") or not os.path.isfile(os.path.join(cmake_dir, "CMakeLists.txt")):
        fail(where, f"build: cmake: {build.get('cmake')!r} is not a folder with a CMakeLists.txt")
    if not build.get("kconfig") or not os.path.isfile(kconfig_path):
        fail(where, f"build: kconfig: {build.get('kconfig')!r} is not a file")
    where = build["kconfig"]
    kconfig = parse_kconfig(kconfig_path)
    if "TRISTREAM" not in kconfig:
        fail(where, "has no config TRISTREAM")
    depends = " && ".join(kconfig["TRISTREAM"]["depends"])
    if "STD_CPP17" not in depends or re.search(r"STD_CPP(98|11|14)\b", depends):
        fail(where, f"TRISTREAM depends on {depends!r}: it must require C++17 or later (CONFIG_STD_CPP17)")
    # Every default of config.h is the default of its Kconfig symbol, and reaches the compiler as it.
    defaults = config_h_defaults(root)
    for macro, value in defaults.items():
        name = "TRISTREAM_" + macro[len("TS_"):]
        if name not in kconfig:
            fail(where, f"has no {name} for config.h's {macro}")
        if kconfig_value(kconfig[name]) != value:
            fail(where, f"{name} defaults to {kconfig[name].get('default')}, config.h's {macro} to {value}")
    where = "zephyr/CMakeLists.txt"

    def definitions(got):
        return {d.split("=", 1)[0]: int(d.split("=", 1)[1], 0) for d in got.get("zephyr_compile_definitions", [])}

    got = zephyr_run(root, os.path.join(work, "defaults"), zephyr_configs(kconfig, {}))
    if definitions(got) != defaults:
        fail(where, f"with Kconfig's defaults defines {definitions(got)}, config.h's defaults are {defaults}")
    # Another configuration (the firmware's of USER_DEFINES) reaches the compiler as set; built and linked.
    overrides = {"TRISTREAM_" + d[len("-DTS_"):].split("=")[0]: int(d.split("=")[1], 0) for d in USER_DEFINES}
    got = zephyr_run(root, os.path.join(work, "configured"), zephyr_configs(kconfig, overrides))
    expected = dict(defaults, **{"TS_" + k[len("TRISTREAM_"):]: v for k, v in overrides.items()})
    if definitions(got) != expected:
        fail(where, f"with {overrides} defines {definitions(got)}, expected {expected}")
    sources = got.get("zephyr_library_sources", [])
    check_sources(where, sources, [os.path.basename(p) for p in core_sources(root)])
    include_dirs = got.get("zephyr_include_directories", []) + got.get("zephyr_library_include_directories", [])
    check_dirs(where, include_dirs)
    # Zephyr's C++ flags with CONFIG_STD_CPP17: -std=c++17, no exceptions or RTTI, freestanding.
    zephyr_flags = ["-Os", "-std=c++17", "-fno-exceptions", "-fno-rtti", "-ffreestanding", "-ffunction-sections",
                    "-fdata-sections", "-Wall"]
    defines = [f"-D{d}" for d in got.get("zephyr_compile_definitions", [])]
    flags = (CPU + zephyr_flags + [f"-I{d}" for d in include_dirs] + defines +
             got.get("zephyr_library_compile_options", []))
    objects = compile_all(where, sources, flags, os.path.join(work, "objects"))
    link_program(where, root, objects, include_dirs, defines, work)
    print(f"zephyr: module.yml, Kconfig's {len(defaults)} settings default as config.h's and reach the compiler; "
          f"{len(sources)} sources built and linked")


# --- The C++ standard -------------------------------------------------------------------------------

def check_cxx_standard(root, work, _tripack):
    include = os.path.join(root, "firmware_core/include")
    for std in ("gnu++11", "gnu++14"):
        for src in core_sources(root):
            expect_cpp17_error(f"firmware_core/src/{os.path.basename(src)} as -std={std}",
                               [CXX] + CPU + [f"-std={std}", "-fno-exceptions", "-fno-rtti", f"-I{include}",
                                              "-fsyntax-only", src])
    print(f"cxx-standard: as gnu++11 and gnu++14 each of the {len(core_sources(root))} sources fails first at "
          f"config.h's #error")


MODES = {"platformio": check_platformio, "arduino": check_arduino, "esp-idf": check_esp_idf,
         "zephyr": check_zephyr, "cxx-standard": check_cxx_standard}


def main(argv):
    if len(argv) < 4 or argv[1] not in MODES:
        print(__doc__, file=sys.stderr)
        return 64
    mode, root, work = argv[1], os.path.abspath(argv[2]), os.path.abspath(argv[3])
    tripack = argv[4] if len(argv) > 4 else None
    if shutil.which(CXX) is None:
        print(f"{mode}: SKIPPED: {CXX} is not installed (tools/install-deps.sh ecosystems)")
        return 77
    try:
        MODES[mode](root, work, tripack)
    except Failure as e:
        print(f"check_ecosystems {mode}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
