#!/bin/sh
# `cpack -G DEB` of the build tree (the package a Debian user installs), unpacked into a scratch
# root with dpkg -x: it holds the tools, man pages, completions, CMake package, JSON Schema and
# templates, its Depends come from dpkg-shlibdeps, the tools run from there, and the README's
# firmware project builds against the unpacked /usr.
#   deb_package.sh BUILD_DIR WORK SOURCE_DIR GENERATOR C_COMPILER
set -eu
build_dir=$1
work=$2
source_dir=$3
for program in cpack dpkg-deb dpkg-shlibdeps; do
    if ! command -v "$program" >/dev/null 2>&1; then
        echo "SKIP: $program is not installed"
        exit 77
    fi
done
rm -rf "$work"
mkdir -p "$work"
cpack -G DEB -B "$work" --config "$build_dir/CPackConfig.cmake" >"$work/cpack.log" 2>&1 || {
    cat "$work/cpack.log"
    exit 1
}
deb=$(ls "$work"/*.deb)
failed=0
fail() { echo "FAIL: $*"; failed=1; }

depends=$(dpkg-deb -f "$deb" Depends)
for library in libyaml-0-2 libxml2 libstdc++6; do
    case "$depends" in *"$library"*) ;; *) fail "Depends lacks $library: $depends" ;; esac
done

root=$work/root
dpkg-deb -x "$deb" "$root"
for file in bin/esi-lint bin/esi-gen bin/esi-diff bin/esi-sii share/man/man1/esi-lint.1 share/man/man1/esi-gen.1 \
            share/man/man5/esi-lint.yaml.5 share/bash-completion/completions/esi-lint \
            share/zsh/vendor-completions/_esi share/fish/vendor_completions.d/esi-lint.fish \
            lib/cmake/libesi/libesiConfig.cmake lib/cmake/libesi/EsiGenerate.cmake \
            share/libesi/schemas/esi-device.schema.json share/libesi/templates/slave_tables.c.mustache; do
    [ -f "$root/usr/$file" ] || fail "the package lacks /usr/$file"
done

version=$("$root/usr/bin/esi-lint" --version) || fail "esi-lint --version failed"
case "$version" in *esi-lint*) ;; *) fail "esi-lint --version printed '$version'" ;; esac
"$root/usr/bin/esi-lint" "$source_dir/samples/esi/example-digital-io.xml" >/dev/null || fail "esi-lint of the sample failed"

cmake -DMODE=native "-DSOURCE_DIR=$source_dir" "-DPREFIX=$root/usr" "-DWORK=$work/firmware" "-DGENERATOR=$4" \
      "-DC_COMPILER=$5" -P "$source_dir/tests/packaging/firmware_project.cmake" || fail "the README firmware project against the package"

[ "$failed" -eq 0 ] && echo "$(basename "$deb"): $(du -k "$deb" | cut -f1) KiB, Depends: $depends"
exit "$failed"
