#!/bin/sh
# The repository is read on its own: no file may cite the specification or
# protocol documents that live outside it (PROTOCOL.md, SPEC.md, ../shared/);
# docs/protocol.md and docs/product.md are the references.
#
# usage: no_outside_citations.sh SOURCE_DIR
set -eu
cd "$1"
pattern='(^|[^a-z/._])(PROTOCOL|SPEC)\.md|\.\./shared/'
hits=$(grep -rInE "$pattern" . --exclude-dir='.git' --exclude-dir='build' --exclude-dir='build-*' \
         --exclude='no_outside_citations.sh' || true)
if [ -n "$hits" ]; then
  echo "$hits"
  echo "FAILED: $(echo "$hits" | wc -l) lines cite documents outside the repository"
  exit 1
fi
echo "ok: no citation of PROTOCOL.md, SPEC.md or ../shared/"
