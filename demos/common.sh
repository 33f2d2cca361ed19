# shellcheck shell=bash disable=SC2034  # (its variables are for the scripts that source it)
# Sourced by every script in demos/ (and by gallery_lib.sh): where the repository, the game data
# and the build are, and the checks that they are there, so each fact is written once.
#
#   root           the repository
#   data           the game data, $NPRQ_DATA (default ../shared/data beside the repository)
#   build          the build, $BUILD (default build/release)
#   engine         $build/bin/nprquake; plugins_dir, its renderer plugins
#   quakespasm_bin, quakespasm_tool   the reference engine and the tool that installs and times it
#   me             the running script's name, for its messages
#
#   die MESSAGE            "me: MESSAGE" on stderr, exit 1
#   require_build [TOOL...]  exit 1 unless nprquake (and each TOOL of $build/bin) is built
#   require_data           exit 1 unless $data/lq1 exists
#   require_command CMD MESSAGE   exit 1 with MESSAGE unless CMD is on PATH
#   quakespasm_installed   status 0 when QuakeSpasm and its timedemo tool are both there
#   usage                  the script's usage text: the lines $usage_lines ("FIRST,LAST") of its
#                          header comment
#   common_option "$@"     the options the scripts share, for the catch-all branch of an option
#                          loop (see below)
#
# Only variables and functions: sourcing it checks nothing, so a script sets its defaults (which
# may use $root), parses its options and answers --help before it asks for the build or the data.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
data=${NPRQ_DATA:-$root/../shared/data}
build=${BUILD:-$root/build/release}
engine=$build/bin/nprquake
plugins_dir=$build/bin/plugins
quakespasm_bin=/usr/games/quakespasm
quakespasm_tool=$root/../shared/tools/quakespasm_timedemo.sh
me=$(basename "$0")

die() {
    echo "$me: $*" >&2
    exit 1
}

# Each message names what is missing and how to get it: the one line a reader needs.
# shellcheck disable=SC2120  # most scripts need the engine alone
require_build() {  # [tool...]: programs of the build besides the engine that the script runs
    local program
    for program in nprquake "$@"; do
        [ -x "$build/bin/$program" ] ||
            die "$program not built at $build/bin/$program: run bash scripts/main.sh"
    done
}

require_data() {
    [ -d "$data/lq1" ] || die "game data not found at $data/lq1 (set NPRQ_DATA)"
}

require_command() {  # command message
    command -v "$1" >/dev/null || die "$2"
}

# A status, not a failure: a script decides whether QuakeSpasm is optional (a column when it is
# there) or needed. quakespasm_tool installs the package when it runs, so a script that only runs
# the tool needs only [ -x "$quakespasm_tool" ].
quakespasm_installed() {
    [ -x "$quakespasm_bin" ] && [ -x "$quakespasm_tool" ]
}

usage() {
    sed -n "${usage_lines:?set by the script}p" "$0"
}

# The catch-all branch of a script's option loop: its own options first, then
#     *) common_option "$@"; shift "$common_shift" ;;
# --out DIR sets $out (every script that takes options has it); anything else is a usage error,
# exit 2: the usage text on stderr where the script sets usage_on_error=1, else one line naming
# the option.
common_option() {
    case $1 in
        --out) out=$2; common_shift=2 ;;
        *)
            if [ "${usage_on_error:-0}" = 1 ]; then usage >&2; else echo "$me: unknown option $1" >&2; fi
            exit 2 ;;
    esac
}
