#!/usr/bin/env bash
# packaging.deb: builds the .deb of this build folder with cpack into a scratch folder, unpacks it with
# dpkg -x into a scratch root and checks what an install gives: the four programs and their --version,
# a check of every installed example, the desktop entry, MIME type, icons, man pages, and a Depends line
# naming the Qt 6 libraries. A missing cpack, dpkg or desktop tool fails the test: it never passes untested.
#   test_deb_package.sh CPACK BUILD_DIR SOURCE_DIR VERSION
set -euo pipefail
cpack=$1 build=$2 source=$3 version=$4
fail() {
  echo "packaging.deb: $*" >&2
  exit 1
}
for tool in "$cpack" dpkg dpkg-deb dpkg-shlibdeps desktop-file-validate update-mime-database; do
  command -v "$tool" >/dev/null || fail "$tool is missing (bash packaging/bootstrap.sh installs it)"
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
started=$SECONDS
"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$work/out" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; fail "cpack failed"; }
deb="$work/out/millexpert_${version}_$(dpkg --print-architecture).deb"
[ -f "$deb" ] || fail "cpack wrote no $(basename "$deb"): $(ls "$work/out")"
echo "packaging.deb: cpack took $((SECONDS - started)) s"

# The control fields: the version, and a Depends line with the Qt 6 libraries and the SQLite driver.
info=$(dpkg-deb -I "$deb")
grep -qx " Version: $version" <<<"$info" || fail "the package's Version is not $version:"$'\n'"$info"
depends=$(sed -n 's/^ Depends: //p' <<<"$info")
for lib in libqt6core6 libqt6gui6 libqt6widgets6 libqt6svg6 libqt6sql6-sqlite; do
  grep -q "\b$lib\b" <<<"$depends" || fail "Depends names no $lib: $depends"
done
recommends=$(sed -n 's/^ Recommends: //p' <<<"$info")
grep -q "\blibqt6sql6-psql\b" <<<"$recommends" || fail "Recommends names no libqt6sql6-psql: $recommends"
echo "packaging.deb: $(grep -o 'Installed-Size: [0-9]*' <<<"$info") kB"

# The files a desktop needs and the man pages, in the package's own listing.
listing=$(dpkg-deb -c "$deb" | awk '{print $NF}')
expected=(./usr/share/applications/millexpert.desktop ./usr/share/mime/packages/millexpert.xml
  ./usr/share/icons/hicolor/scalable/apps/millexpert.svg)
for size in 16 24 32 48 64 128 256; do expected+=("./usr/share/icons/hicolor/${size}x${size}/apps/millexpert.png"); done
for program in millexpert millexpert-cli millexpert-report millexpert-plot; do
  expected+=("./usr/bin/$program" "./usr/share/man/man1/$program.1.gz")
done
for file in "${expected[@]}"; do
  grep -qxF "$file" <<<"$listing" || fail "the package has no $file"
done

# Installed into a scratch root: every program prints the version, without a display. What the
# programs write (Qt's runtime folder, settings) stays in the scratch folder.
root="$work/root"
dpkg -x "$deb" "$root"
mkdir -m 0700 "$work/home" "$work/runtime"
export HOME="$work/home" XDG_RUNTIME_DIR="$work/runtime" XDG_CONFIG_HOME="$work/home/.config"
bin="$root/usr/bin"
[ "$("$bin/millexpert-cli" --version)" = "millexpert-cli $version" ] ||
  fail "millexpert-cli --version: '$("$bin/millexpert-cli" --version)', not 'millexpert-cli $version'"
for program in millexpert millexpert-report millexpert-plot; do
  out=$(env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$bin/$program" --version) ||
    fail "$program --version failed: $out"
  [ "${out##* }" = "$version" ] || fail "$program --version: '$out', not version $version"
done
for program in millexpert millexpert-cli millexpert-report millexpert-plot; do
  zcat "$root/usr/share/man/man1/$program.1.gz" | grep -q "$version" || fail "man page of $program names no $version"
done

# The desktop entry is valid and names the icon and the MIME type; the MIME database built from the
# installed XML, as shared-mime-info's trigger builds it on an install, maps *.mxproj to that type.
desktop="$root/usr/share/applications/millexpert.desktop"
desktop-file-validate "$desktop" || fail "desktop-file-validate: $desktop is not valid (above)"
grep -qx "Icon=millexpert" "$desktop" || fail "the desktop entry names no Icon=millexpert"
grep -qx "MimeType=application/x-millexpert-project;" "$desktop" || fail "the desktop entry names no MIME type"
update-mime-database "$root/usr/share/mime" || fail "update-mime-database refused the installed MIME XML"
grep -qxF "50:application/x-millexpert-project:*.mxproj" "$root/usr/share/mime/globs2" ||
  fail "the MIME database maps no *.mxproj to application/x-millexpert-project"
grep -qxF "application/x-millexpert-project:millexpert" "$root/usr/share/mime/icons" ||
  fail "the MIME database gives application/x-millexpert-project no millexpert icon"
for size in 16 48 256; do  # a PNG's width and height are the big-endian words at bytes 16 and 20
  png="$root/usr/share/icons/hicolor/${size}x${size}/apps/millexpert.png"
  dims=$(od -An -tu1 -j16 -N8 "$png" | awk '{print $3 * 256 + $4, $7 * 256 + $8}')
  [ "$dims" = "$size $size" ] || fail "$png is $dims pixels, not $size x $size"
done

# The examples with every file they name: the installed folder holds the source tree's projects/, and
# each project checks; the tap-test example's lobes read its installed UFF files.
projects="$root/usr/share/millexpert/projects"
diff <(cd "$source/projects" && find . -type f | sort) <(cd "$projects" && find . -type f | sort) ||
  fail "the installed examples differ from projects/ (above)"
count=0
for project in "$projects"/*.mxproj; do
  "$bin/millexpert-cli" check "$project" >/dev/null || fail "millexpert-cli check $project failed"
  count=$((count + 1))
done
"$bin/millexpert-cli" lobes "$projects/tap-test-example.mxproj" --tool T9 --dynamics measured \
  --from 3000 --to 3100 --step 100 >/dev/null || fail "lobes on the installed tap-test example failed"
# The batch recipes, as docs/shop-scale.md names them.
for recipe in millexpert-batch.sbatch millexpert-batch-job.yaml; do
  cmp -s "$root/usr/share/millexpert/batch/$recipe" "$(find "$source/packaging" -name "$recipe")" ||
    fail "the package lacks usr/share/millexpert/batch/$recipe, or it differs from packaging/"
done
# The installed window opens its default example from <root>/usr/share beside its bin/ (the system's
# data folders emptied, the source tree out of an installed copy's reach): without it, the window would
# show its start page, take no screenshot and exit 1 after 60 s.
mkdir "$work/data"
XDG_DATA_DIRS="$work/data" XDG_DATA_HOME="$work/data" QT_QPA_PLATFORM=offscreen \
  "$bin/millexpert" --screenshot "$work/window.png" >"$work/window.log" 2>&1 ||
  { cat "$work/window.log" >&2; fail "the installed millexpert did not open its default example"; }
[ -s "$work/window.png" ] || fail "the installed millexpert wrote no screenshot"
echo "packaging.deb: $count installed examples check; passed in $((SECONDS - started)) s"
