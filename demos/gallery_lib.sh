# Shared by the style galleries (technical_gallery.sh, illustrative_gallery.sh): run the engine
# on the showroom and on paused demo.dem frames with a list of settings, and lay the screenshots
# out as labelled contact sheets (ImageMagick). Source it after setting:
#   style     the plugin under test, e.g. technical
#   compare_styles  (optional) the styles compared on the demo frames, $style last (default
#             "classic $style")
# It sources common.sh ($root, $data, $engine, ...); then set, before gallery_init:
#   defaults  console commands every picture starts from (the cvar defaults written out, so a
#             user's config cannot leak in)
#   settings  array of "name|commands" pictures (commands on top of the defaults)
#   out       the output folder
#   engine_args  (optional) extra command-line arguments for every run, e.g. "+vo_enable 1"
# Then: gallery_init; gallery_showroom; gallery_demo "300 600 760"; compare_sheets; group ...
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

gallery_init() {
    require_build
    require_data
    require_command montage "needs ImageMagick"
    work=$(mktemp -d)
    trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
    mkdir -p "$out" "$work/user/id1" "$work/user/lq1"
}

script() {  # scene-prefix -> a config script taking every picture
    local prefix=$1 entry name cmds
    for entry in "${settings[@]}"; do
        name=${entry%%|*}
        cmds=${entry#*|}
        echo "$defaults" | tr '\n' ' '
        echo
        echo "$cmds"
        echo "wait; wait; screenshot $work/${prefix}_$name.png"
    done
}

# The showroom at a fixed instant, every setting.
gallery_showroom() {
    script showroom > "$work/user/id1/gallery.cfg"
    SDL_VIDEODRIVER=offscreen "$engine" -userdir "$work/user" -basedir "$work/nodata" -width 640 \
        -height 480 +con_notifytime 0 ${engine_args:-} +r_plugin "$style" +showroom_time 5 +wait \
        +exec gallery.cfg \
        +quit > "$work/showroom.log" 2>&1
}

# demo.dem: every style in `compare_styles` (the last one $style) on the same paused frames; at
# the last frame every setting of $style too, then quit.
compare_styles=${compare_styles:-"classic $style"}
gallery_demo() {  # "frame frame ..."
    local frames=($1) f last commands s
    last=${frames[-1]}
    for f in "${frames[@]}"; do
        commands="pause 1"
        for s in $compare_styles; do
            commands+="; r_plugin $s; wait; wait; screenshot $work/${s}_$f.png"
        done
        if [ "$f" = "$last" ]; then commands+="; exec gallery.cfg"; else commands+="; pause 0"; fi
        echo "demo_at $f \"$commands\""
    done > "$work/user/lq1/frames.cfg"
    script demo > "$work/user/lq1/gallery.cfg"
    echo "quit" >> "$work/user/lq1/gallery.cfg"
    SDL_VIDEODRIVER=offscreen "$engine" -userdir "$work/user" -basedir "$data" -game lq1 -width 640 \
        -height 480 +con_notifytime 0 +scr_centertime 0 +scr_drawhud 0 +gl_polyblend 0 \
        ${engine_args:-} +r_plugin "$style" +exec frames.cfg +timedemo demo > "$work/demo.log" 2>&1 ||
        true
}

sheet() {  # output title files...
    local output=$1 title=$2; shift 2
    montage "$@" -tile "$#x1" -geometry 480x360+4+4 -font DejaVu-Sans -pointsize 16 -title "$title" \
        -quality 85 "$output"
}

labelled() {  # prefix name caption -> path of a labelled copy
    local src=$work/$1_$2.png dst=$work/label_$1_$2.png
    [ -f "$src" ] || { echo "$me: missing $src (see $work/*.log)" >&2; return 1; }
    montage -label "$3" "$src" -geometry +0+0 -font DejaVu-Sans -pointsize 16 "$dst"
    echo "$dst"
}

compare_sheets() {  # "frame frame ..." -> one sheet per frame with every compared style
    local f s files
    for f in $1; do
        files=()
        for s in $compare_styles; do files+=("$(labelled "$s" "$f" "$s")"); done
        sheet "$out/demo_frame_$f.jpg" "demo.dem frame $f" "${files[@]}"
    done
}

group() {  # output title names... -> a sheet per scene (showroom, demo)
    local output=$1 title=$2 scene name files=(); shift 2
    for scene in showroom demo; do
        files=()
        for name in "$@"; do files+=("$(labelled "$scene" "$name" "$name")"); done
        sheet "$out/${scene}_$output.jpg" "$title" "${files[@]}"
    done
}
