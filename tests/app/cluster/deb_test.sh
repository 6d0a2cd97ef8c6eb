#!/bin/bash
# The .deb depends on the package of every shared library the binary asks the loader for, and
# installs the binary, its documentation and the Slurm scripts. The expected dependencies are
# derived here independently of dpkg-shlibdeps: each NEEDED entry of the ELF file, resolved by the
# loader's cache (ldconfig -p) and owned by a package (dpkg -S).
# usage: deb_test.sh PACKAGE_DIR WORK_DIR
set -euo pipefail
package_dir=$1 work=$2
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
debs=("$package_dir"/tumble_*_amd64.deb)
{ [ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ]; } || fail "expected one tumble_*_amd64.deb in $package_dir"
deb=${debs[0]}
[[ $(basename "$deb") =~ ^tumble_[0-9]+\.[0-9]+\.[0-9]+_amd64\.deb$ ]] || fail "named $(basename "$deb")"
rm -rf "$work" && mkdir -p "$work" && dpkg -x "$deb" "$work"
for f in usr/bin/tumble usr/share/doc/tumble/README.md usr/share/doc/tumble/docs/cluster.md \
  usr/share/tumble/slurm/submit.sh usr/share/tumble/slurm/render-shards.sbatch \
  usr/share/tumble/slurm/join.sbatch usr/share/tumble/slurm/render-sweep.sbatch; do
  [ -e "$work/$f" ] || fail "the package does not install /$f"
done
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
count=0
for lib in $(objdump -p "$work/usr/bin/tumble" | awk '/NEEDED/ {print $2}'); do
  path=$(ldconfig -p | awk -v l="$lib" '$1 == l && /x86-64/ && !found {print $NF; found = 1}')
  [ -n "$path" ] || fail "the loader does not know $lib"
  # Every pipe here reads all of its input (no `head`, no awk `exit`): a writer killed by SIGPIPE
  # fails the pipeline under pipefail, which failed this test at random under load (seen once in
  # a full parallel run, right after libm).
  owner=$(dpkg -S "$(readlink -f "$path")" 2> /dev/null | awk -F: 'NR == 1 {print $1}') ||
    owner=$(dpkg -S "$path" | awk -F: 'NR == 1 {print $1}')
  [ -n "$owner" ] || fail "no package owns $path ($lib)"
  echo "$lib -> $owner"
  [[ ", $depends," == *", $owner "* || ", $depends," == *", $owner,"* ]] ||
    fail "$lib comes from $owner, which Depends does not name"
  count=$((count + 1))
done
[ "$count" -ge 8 ] || fail "only $count NEEDED libraries found: the check would prove little"
# The Python module, when the build made it: installed into Debian's Python path, and importable
# from there by Debian's Python (nothing of the build tree on its path).
module=usr/lib/python3/dist-packages/tumble
if [ -e "$work/$module/__init__.py" ]; then
  [ -e "$work/$module/_tumble.pyi" ] || fail "the package does not install /$module/_tumble.pyi"
  rows=$(cd "$work" && PYTHONPATH="$work/usr/lib/python3/dist-packages" /usr/bin/python3 -c \
    'import tumble; print(len(tumble.simulate("default", duration=0.5)))')
  [ "$rows" = 121 ] || fail "the installed module simulated $rows rows, not 121"
  echo "the installed module imports and simulates ($rows rows)"
fi
echo "PASS: $count linked libraries, each from a package in Depends"
