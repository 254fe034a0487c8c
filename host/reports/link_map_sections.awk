# link_map_sections.awk - the input sections of a GNU ld map file (-Map),
# one line each: "name size object", size in bytes. A section whose name is
# too long for its column is split over two lines in the map; both forms are
# read. Only the sections in the image: the map's list of input sections the
# link discarded (--gc-sections), which comes first, is skipped. Used by
# embedded_report.sh and twin_firmware_report.sh.
function hex(text,    i, value) { # "0x1a4" -> 420 (mawk has no strtonum)
    value = 0
    for (i = 3; i <= length(text); ++i)
        value = value * 16 + index("0123456789abcdef", tolower(substr(text, i, 1))) - 1
    return value
}
/^Linker script and memory map/ { in_image = 1; next }
!in_image { next }
/^ \.[A-Za-z_.0-9]+$/ { pending = $1; next }
pending != "" && NF == 3 && $1 ~ /^0x/ { print pending, hex($2), $3; pending = ""; next }
/^ \.[A-Za-z_.0-9]+ +0x/ && NF == 4 { print $1, hex($3), $4 }
{ pending = "" }
