#!/usr/bin/env bash
# Every scene script (scenes/*/make_*.py) run on a copy of scenes/ must write exactly the files
# that are committed: a script changed without its scene regenerated, or one that is not
# deterministic, fails here with the files that differ.
# Usage: regenerate.sh SOURCE_DIR [PYTHON]
set -u
source_dir=$1 python=${2:-python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$source_dir/scenes" "$work/scenes"
failures=0 scripts=0
for script in "$work"/scenes/*/make_*.py; do
    name=${script#"$work/"}
    scripts=$((scripts + 1))
    if ! (cd "$(dirname "$script")" && "$python" "$(basename "$script")" >/dev/null); then
        echo "FAIL [$name runs]"
        failures=$((failures + 1))
    fi
done
# What the scripts wrote, against the committed scenes (new files count too), except what a
# scene's .gitignore names: files a script makes that are too large to commit (texture-plane's
# ground.png), which must not be compared with a copy a user may or may not have made.
excludes=(-x __pycache__)
for ignore in "$source_dir"/scenes/*/.gitignore; do
    [ -f "$ignore" ] || continue
    while IFS= read -r pattern; do
        case $pattern in ''|'#'*) continue ;; esac
        excludes+=(-x "$pattern")
    done < "$ignore"
done
if differences=$(diff -rq "$source_dir/scenes" "$work/scenes" "${excludes[@]}"); then
    echo "ok   [$scripts scripts regenerate their scenes byte for byte]"
else
    echo "FAIL [the scripts' output differs from the committed scenes:]"
    echo "$differences"
    failures=$((failures + 1))
fi
[ "$scripts" -gt 0 ] || { echo "FAIL [no scene scripts found under $source_dir/scenes]"; failures=$((failures + 1)); }
exit $((failures > 0))
