# baseline_tree.sh - sourced by the reports that compare this tree with an earlier
# commit (baseline_check.sh, bench.sh). baseline_tree COMMIT: checks COMMIT out in
# build/baseline/src (a git worktree, reused while it is the same commit), builds its
# beamslider in both precisions there, and prints the full commit.
baseline_tree() {
    _commit=$(git rev-parse --verify "$1^{commit}")
    _src=build/baseline/src
    if [ ! -d "$_src" ] || [ "$(git -C "$_src" rev-parse HEAD 2>/dev/null)" != "$_commit" ]; then
        git worktree remove --force "$_src" 2>/dev/null || rm -rf "$_src"
        git worktree prune
        mkdir -p build/baseline
        git worktree add --detach "$_src" "$_commit" >&2
    fi
    for _real in double float; do
        make -C "$_src" --no-print-directory -s REAL=$_real build/$_real/beamslider >&2
    done
    echo "$_commit"
}
