#!/bin/sh
# tests/docs.sh PHOTON -- the documentation says what is true: run from the top of the
# repository by tests/test_docs.c.
#
#  1. Every file a document names (a path under scenes/, reference/, src/, tests/, scripts/)
#     exists. Placeholders (NAME, FILE, *, $VAR) are not files and are passed over.
#  1b. Every `name()` a document shows is a function or macro of src/ or tests/.
#  1c. Every section of a mode's paper that a document or a source file cites is one the
#     paper has (tests/data/paper-sections.txt).
#  2. Every option a document shows on a `./photon` command line is one that photon's
#     --help all (or, on a subcommand's line, the subcommand's --help) lists.
#  3. The README's commands work as shown: every line of its ```sh blocks that starts with
#     `./photon` or `mkdir` runs, in order, in an empty directory that sees only scenes/ and
#     reference/, and must exit 0. Renders get `--quality preview` appended (an explicit
#     option still wins over it; one with its own --quality keeps it, as an option is
#     given once), so the whole README runs in well under a minute.
#  4. The reference suite's table (reference/suite.txt) and its files agree: every line has
#     reference/NAME.pfm, NAME.png and, but for 2008 and 2009, NAME-var.pfm (for those,
#     NAME-error.pfm and NAME-blocks.pfm, which their row's command names), and a
#     measured row in reference/suite.md; every PFM in reference/ has its line; every
#     scene the table names exists, every scenes/analytic/ scene has a reference, and
#     every option the table gives is one photon's --help all lists. Nothing is rendered.
#  5. No include circle: module dir/x is src/dir/x.c with src/dir/x.h, and depends on every
#     module whose header one of its two files includes (#include "..." resolved from the
#     including file's folder); no module may depend on itself round a circle (README:
#     Where things are). Each circle is printed as the shortest way back to one of its
#     modules, starting from the least name: "a -> b -> a".
# Prints one line per problem and "docs: N problems"; exits 1 when there is any.
set -u
photon=$1
case $photon in /*) ;; *) photon=$(pwd)/$photon ;; esac
docs="README.md src/modes/README.md src/modes/measured.md reference/README.md reference/suite.md scripts/README.md tests/bench/README.md"
problems=0
problem() { echo "docs: $*"; problems=$((problems + 1)); }

# 1. Files named.
for doc in $docs; do
    [ -f "$doc" ] || continue
    dir=$(dirname "$doc")
    grep -oE '(\.\./)?(scenes|reference|src|tests|scripts)/[A-Za-z0-9_.+/-]*[A-Za-z0-9_]' "$doc" |
        sort -u | while read -r path; do
            case $path in *[A-Z][A-Z][A-Z]*|*'*'*) continue ;; esac
            [ -e "$path" ] || [ -e "$dir/$path" ] || echo "$doc names $path, which does not exist"
        done
done > docs-missing.tmp
while read -r line; do problem "$line"; done < docs-missing.tmp
rm -f docs-missing.tmp

# 1b. Functions named: every `name()` a document shows is defined in src/ or tests/ (a
# function at the start of its line, or a macro), apart from the outside ones listed here:
# the C library's clock(), time() and ftell(), Embree's rtcIntersect1(), Radiance's
# posgradient().
outside=" clock time ftell rtcIntersect1 posgradient "
for doc in $docs tests/data/README.md; do
    [ -f "$doc" ] || continue
    grep -oE '`[A-Za-z_][A-Za-z0-9_]*\(\)`' "$doc" | tr -d '`()' | sort -u |
        while read -r name; do
            case $outside in *" $name "*) continue ;; esac
            grep -rqE "^([A-Za-z_].*[ *])?$name\(|^#define $name\(" --include='*.c' \
                --include='*.h' src tests ||
                echo "$doc names $name(), which nothing in src/ or tests/ defines"
        done
done > docs-functions.tmp
while read -r line; do problem "$line"; done < docs-functions.tmp
rm -f docs-functions.tmp

# 1c. Sections cited: every "Sec. N" of a mode's paper that a document or a source file
# cites is a section of that paper (tests/data/paper-sections.txt). A citation belongs to
# the paper named last before it in its paragraph ("Jensen 1996", "Jensen and
# Christensen 1994", "... Jensen 2008"); with none named, to the paper of the mode file
# (src/modes/jensen1994*, jensen1996*, photons.*, ppm2008*, ppm_*) or of the README part
# (## `--mode 1994` ...). A paragraph ends at an empty line, a comment's end or a heading.
# Citations of other works (Veach 1997, RFC 1951) are not checked.
for file in $docs $(find src -name '*.[ch]' | sort); do
    [ -f "$file" ] && printf '%s\n' "$file"
done | xargs awk '
FNR == 1 && !outlines_read {
    while ((getline line < "tests/data/paper-sections.txt") > 0) {
        if (line ~ /^#/ || line == "") continue
        n = split(line, word, " ")
        listed[word[1]] = 1
        for (i = 2; i <= n; i++) section[word[1], word[i]] = 1
    }
    outlines_read = 1
}
FNR == 1 {
    home = ""
    if (FILENAME ~ /src\/modes\/jensen1994/) home = "1994"
    else if (FILENAME ~ /src\/modes\/(jensen1996|photons\.)/) home = "1996"
    else if (FILENAME ~ /src\/modes\/(ppm2008|ppm_)/) home = "2008"
    paper = home
}
/^#/ && FILENAME ~ /\.md$/ {
    if ($0 ~ /^## /) home = match($0, /--mode (1994|1996|2008|2009)/) ? substr($0, RSTART + 7, 4) : ""
    paper = home
}
{
    text = $0
    while (match(text, /(Jensen (and|&) Christensen 1994|Jensen 1996|Jensen 2008|Jensen 2009|[A-Z][a-z]+ (19|20)[0-9][0-9]|RFC [0-9]+|Secs?\.? ?[0-9]+(\.[0-9]+)*)/)) {
        token = substr(text, RSTART, RLENGTH); text = substr(text, RSTART + RLENGTH)
        if (token ~ /^Sec/) {
            number = token; sub(/^Secs?\.? ?/, "", number)
            if (paper == "" || paper == "other") continue
            if (!(paper in listed)) print FILENAME ":" FNR ": cites Sec. " number " of " paper ", a paper tests/data/paper-sections.txt does not outline"
            else if (!((paper, number) in section)) print FILENAME ":" FNR ": cites Sec. " number " of the " paper " paper, which has no such section"
        } else if (token ~ /1994$/ && token ~ /Christensen/) paper = "1994"
        else if (token ~ /^Jensen (1996|2008|2009)$/) paper = substr(token, 8)
        else paper = "other"
    }
}
/^[ \t]*$/ || /\*\// { paper = home }
' > docs-sections.tmp
while read -r line; do problem "$line"; done < docs-sections.tmp
rm -f docs-sections.tmp

# 2. Options shown on command lines.
usage=$("$photon" --help all 2>&1)
# A subcommand's line may show its own options, listed by its own --help.
subcommands="compare plot merge probe export convert"
for doc in $docs; do
    [ -f "$doc" ] || continue
    grep -E '^\s*(\./)?photon ' "$doc" | while read -r line; do
        sub=$(printf '%s\n' "$line" | sed -E 's#^\s*(\./)?photon ##; s# .*##')
        case " $subcommands " in *" $sub "*) own=$("$photon" "$sub" --help 2>&1) ;; *) own= ;; esac
        printf '%s\n' "$line" | grep -oE '(^|\s)--[a-z][a-z0-9-]*' | tr -d ' \t' |
            while read -r option; do
                printf '%s\n%s\n' "$usage" "$own" | grep -qe "$option" ||
                    echo "$doc shows $option, which photon --help all does not list"
            done
    done | sort -u
done > docs-options.tmp
while read -r line; do problem "$line"; done < docs-options.tmp
rm -f docs-options.tmp

# 3. The README's commands, in a scratch directory.
top=$(pwd)
scratch=$(mktemp -d)
ln -s "$top/scenes" "$scratch/scenes"
ln -s "$top/reference" "$scratch/reference"
awk '/^```sh$/ { inside = 1; next } /^```/ { inside = 0 } inside && /^(\.\/photon|mkdir) / { print }' \
    README.md > "$scratch/commands"
n=0
while read -r command; do
    n=$((n + 1))
    case $command in
    "./photon compare"*|"./photon plot"*|"./photon merge"*|"./photon probe"*|"./photon export"*|\
    "./photon convert"*) run=$command ;;
    ./photon*--quality*) run="$command --no-progress" ;; # an option is given once
    ./photon*) run="$command --quality preview --no-progress" ;;
    *) run=$command ;;
    esac
    run=$(printf '%s\n' "$run" | sed "s#^\./photon#$photon#")
    if ! (cd "$scratch" && sh -c "$run" > "$scratch/log" 2>&1); then
        problem "README command fails: $command"
        sed 's/^/    /' "$scratch/log" | head -n 5
    fi
done < "$scratch/commands"
rm -rf "$scratch"
[ "$n" -gt 0 ] || problem "no ./photon command found in README.md's sh blocks"
# 4. The reference suite: the table's lines (comments and blank lines dropped), fields
#    trimmed; field 1 the name, 2 the scene, 3 the options, 5 the check's options.
suite=reference/suite.txt
sed -e '/^[[:space:]]*#/d' -e '/^[[:space:]]*$/d' "$suite" |
    awk -F'|' '{ for (i = 1; i <= NF; i++) gsub(/^[ \t]+|[ \t]+$/, "", $i)
                 print $1 "|" $2 "|" $3 "|" $5 }' > docs-suite.tmp
{
    while IFS='|' read -r name scene options check; do
        [ -f "$scene" ] || echo "$suite: $name renders $scene, which does not exist"
        for file in "$name.pfm" "$name.png"; do
            [ -f "reference/$file" ] || echo "$suite: $name has no reference/$file"
        done
        row=$(grep "^| \`$name.pfm\` |" reference/suite.md || :)
        case " $options " in
        *" --mode 2008 "* | *" --mode 2009 "*) # no variance image: its error statement
            for kept in error blocks; do
                [ -f "reference/$name-$kept.pfm" ] ||
                    echo "$suite: $name has no reference/$name-$kept.pfm"
                case $row in *"reference/$name-$kept.pfm"*) ;;
                *) echo "reference/suite.md: $name's row does not name reference/$name-$kept.pfm" ;;
                esac
            done ;;
        *) [ -f "reference/$name-var.pfm" ] || echo "$suite: $name has no reference/$name-var.pfm" ;;
        esac
        case $row in
        "" | *"not rendered yet"*) echo "reference/suite.md has no measured row for $name (make reference ONLY=$name)" ;;
        esac
        for option in $options $check; do
            case $option in
            --*) printf '%s\n' "$usage" | grep -qe "$option" ||
                echo "$suite: $name shows $option, which photon --help all does not list" ;;
            esac
        done
    done < docs-suite.tmp
    for file in reference/*.pfm; do
        name=$(basename "$file" .pfm)
        made=${name%-var}
        made=${made%-error}
        made=${made%-blocks}
        grep -q "^$name|" docs-suite.tmp || grep -q "^$made|" docs-suite.tmp ||
            echo "$file is in reference/ but no line of $suite makes it"
    done
    for scene in scenes/analytic/*.scene; do
        cut -d'|' -f2 docs-suite.tmp | grep -qx "$scene" ||
            echo "$scene has no reference in $suite"
    done
} > docs-suite-problems.tmp
while read -r line; do problem "$line"; done < docs-suite-problems.tmp
rm -f docs-suite.tmp docs-suite-problems.tmp

# 5. Include circles. One awk reads every include line of src/, resolves its path, and looks
#    from each module for the shortest way back to it (breadth first).
find src -name '*.[ch]' | sort | xargs awk '
function module(path) { sub(/^src\//, "", path); sub(/\.[ch]$/, "", path); return path }
function resolve(dir, name,    n, part, i, k, kept, path) {
    n = split(dir "/" name, part, "/")
    k = 0
    for (i = 1; i <= n; i++)
        if (part[i] == "..") k--
        else if (part[i] != "." && part[i] != "") kept[++k] = part[i]
    path = kept[1]
    for (i = 2; i <= k; i++) path = path "/" kept[i]
    return path
}
/^[ \t]*#[ \t]*include[ \t]*"/ {
    name = $0; sub(/^[^"]*"/, "", name); sub(/".*/, "", name)
    dir = FILENAME; sub(/\/[^\/]*$/, "", dir)
    a = module(FILENAME); b = module(resolve(dir, name))
    if (a != b && !((a, b) in edge)) { edge[a, b] = 1; after[a] = after[a] " " b; node[a] = 1 }
}
END {
    for (start in node) {
        split("", from); split("", seen)
        head = 1; tail = 1; queue[1] = start; last = ""
        while (head <= tail && last == "") {
            at = queue[head++]
            n = split(after[at], next_of, " ")
            for (i = 1; i <= n && last == ""; i++)
                if (next_of[i] == start) last = at
                else if (!(next_of[i] in seen)) {
                    seen[next_of[i]] = 1; from[next_of[i]] = at; queue[++tail] = next_of[i]
                }
        }
        if (last == "") continue
        k = 0  # ring[k], ..., ring[1]: start -> ... -> last, the way back found
        for (m = last; m != start; m = from[m]) ring[++k] = m
        ring[++k] = start
        least = 1
        for (i = 2; i <= k; i++) if (ring[i] < ring[least]) least = i
        text = ring[least]; i = least
        do { i = i == 1 ? k : i - 1; text = text " -> " ring[i] } while (i != least)
        if (!(text in told)) { told[text] = 1; print text }
    }
}' | sort > docs-circles.tmp
while read -r line; do problem "include circle: $line"; done < docs-circles.tmp
rm -f docs-circles.tmp

echo "docs: $n README commands run, $problems problems"
[ "$problems" -eq 0 ]
