#!/usr/bin/env bash
# Renders pages of the worked solution (`gacli derive F --format latex --standalone --steps`)
# to the PNG files in docs/ that README links: the rolling disk's and Chaplygin's ball's
# documents whole, and the sphere on the turntable's second page.
# Needs pdflatex (texlive-latex-base, texlive-latex-recommended) and pdftoppm (poppler-utils).
# Run from anywhere: bash docs/make_pages.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export PYTHONPATH="$root${PYTHONPATH:+:$PYTHONPATH}"

render() {  # system, output prefix, first page, last page
  local name=$1 prefix=$2 first=$3 last=$4
  python -m gacli derive "$root/systems/$name.yaml" --format latex --standalone --steps --output "$work/$name.tex"
  (cd "$work" && pdflatex -interaction=nonstopmode -halt-on-error "$name.tex" >/dev/null)
  pdftoppm -r 80 -png -f "$first" -l "$last" "$work/$name.pdf" "$work/$prefix"
  for page in "$work/$prefix"-*.png; do
    number="${page##*-}"; number="${number%.png}"; number=$((10#$number))
    mv "$page" "$root/docs/${prefix}_page${number}.png"
  done
}

rm -f "$root"/docs/steps_rolling_disk_page*.png "$root"/docs/steps_chaplygin_ball_page*.png
render rolling_disk steps_rolling_disk 1 9
render chaplygin_ball steps_chaplygin_ball 1 9
render sphere_on_turntable steps_sphere 2 2
ls "$root"/docs/steps_*.png
