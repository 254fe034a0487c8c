# section.sh - sourced by the report scripts of host/reports that own a marked
# section of a page (between the lines <!-- NAME --> and <!-- /NAME -->, the
# rest of the page hand-written). Sourced, not run.
#
# write_section OUT NAME FILE: FILE's lines become the section NAME of OUT.
# A new OUT is FILE whole. An OUT without both marker lines is refused with a
# message (status 1) and left as it is: without them the splice would drop
# the hand-written rest of the page.
write_section() {
    if [ ! -e "$1" ]; then
        cp "$3" "$1"
        return 0
    fi
    if ! grep -q "^<!-- $2 -->\$" "$1" || ! grep -q "^<!-- /$2 -->\$" "$1"; then
        echo "$1: the section $2 needs both lines <!-- $2 --> and <!-- /$2 -->; not overwritten (the section is in $3)" >&2
        return 1
    fi
    awk -v section="$3" -v opening="<!-- $2 -->" -v closing="<!-- /$2 -->" '
        $0 == opening { print; while ((getline line < section) > 0) print line; skip = 1; next }
        $0 == closing { skip = 0 }
        !skip' "$1" > "$1.section.$$" && cat "$1.section.$$" > "$1"
    status=$?
    rm -f "$1.section.$$"
    return $status
}
