#!/usr/bin/env bash
# The user guide builds and its links hold: `mdbook build docs` (into target/book), then
# LinkChecker on the built HTML, local links and #anchors only (no external URL is fetched),
# and on README.md's links into the guide (LinkChecker's MarkdownCheck plugin). Installs
# what is missing: mdbook from crates.io (pinned), linkchecker from Debian. CI runs it.
# Usage: scripts/check-book.sh
set -euo pipefail
cd "$(dirname "$0")/.."
MDBOOK_VERSION=0.5.4
export PATH="${CARGO_HOME:-$HOME/.cargo}/bin:$PATH"   # where cargo install puts it

if ! command -v mdbook >/dev/null || [ "$(mdbook --version)" != "mdbook v$MDBOOK_VERSION" ]; then
  # Without the `serve` and `watch` features: no web server or file watcher to build.
  cargo install mdbook --locked --version "$MDBOOK_VERSION" --no-default-features --features search --quiet
fi
if ! command -v linkchecker >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq linkchecker >/dev/null
fi

rm -rf target/book
mdbook build docs 2>&1 | tee target/book.log
# mdbook reports a missing chapter file or a bad SUMMARY.md as an error but links only as
# warnings; fail on any.
! grep -E '^ *(WARN|ERROR)|warning|error' target/book.log \
  || { echo "mdbook build docs: warnings or errors above" >&2; exit 1; }

# LinkChecker run as root drops to user nobody, who may not read this clone (under /root, say):
# it checks a world-readable copy of the tracked files and the built guide.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$tmp"
mkdir -p "$tmp/target" && cp -r target/book "$tmp/target/"
chmod -R a+rX "$tmp"
cfg=$tmp/linkcheckerrc
cat >"$cfg" <<'RC'
[checking]
threads=4
[filtering]
checkextern=0
# a Markdown file is parsed by MarkdownCheck, not by LinkChecker's own parsers, which say so
ignorewarnings=url-content-type-unparseable
# Not checked: what MarkdownCheck takes for a link in text such as "[a, b]: the errors" (every
# real link here names a file with an extension: .md, .toml, .png, ...), and print.html, every
# chapter again on one page (checked once, in the chapters).
ignore=/[^/.]*$
  print\.html$
[AnchorCheck]
[MarkdownCheck]
filename_re=.*\.md$
[output]
verbose=0
RC
# The built guide: every local link and anchor; then README.md's links (MarkdownCheck parses
# the chapters they reach too: their links are checked twice, their anchors once, in HTML).
linkchecker --config "$cfg" --no-status "$tmp/target/book/index.html"
linkchecker --config "$cfg" --no-status "$tmp/README.md"
echo "user guide built (target/book) and its links checked"
