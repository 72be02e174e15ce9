#!/usr/bin/env bash
# README's shell commands, run on a fresh clone of the working tree: the files git tracks, as
# they are now, copied to WORK_DIR/clone (a file README uses that git does not track is missing
# there, as on a user's clone). Every line of every ```sh block runs, in the clone, each block in
# one shell (so a block's variables hold for its later lines), with HOME in WORK_DIR (so
# ~/.local is a scratch prefix); the test fails when any command fails.
# The lines that build (make ..., cmake --preset ..., cmake --build ...) are not run: each
# build/PRESET/ folder the commands name is this test's build, BUILD_DIR, which is what they
# would have built (make run, CI and the package tests build and check the presets themselves).
# Usage: readme_commands.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -euo pipefail

source_dir=$1
build_dir=$2
work_dir=$3
clone=$work_dir/clone

rm -rf "$work_dir"
mkdir -p "$clone" "$work_dir/home" "$work_dir/blocks"
# The tracked files that exist now (one deleted in the working tree is deleted in the clone too).
git -C "$source_dir" ls-files -z --cached |
  (cd "$source_dir" && while IFS= read -r -d '' file; do
     [ -e "$file" ] && printf '%s\0' "$file"
   done) |
  tar -C "$source_dir" --null -T - -cf - | tar -C "$clone" -xf -

# The configure presets, whose build/PRESET folders are this test's build.
presets=$(cd "$clone" && cmake --list-presets | sed -n 's/^ *"\([^"]*\)".*/\1/p')

builds() {  # is line $1 one that builds?
  [[ $1 =~ ^[[:space:]]*(make([[:space:]]|$)|cmake[[:space:]]+--preset|cmake[[:space:]]+--build) ]]
}

# Each ```sh block becomes a script in WORK_DIR/blocks, named after its first line in README.
blocks=()
in_block=false
continued=false  # the line before ended with a backslash
number=0
skipped=0
while IFS= read -r line || [ -n "$line" ]; do
  number=$((number + 1))
  if ! $in_block; then
    if [[ $line =~ ^\`\`\`sh[[:space:]]*$ ]]; then
      in_block=true
      script=$work_dir/blocks/README.md-line-$((number + 1)).sh
      blocks+=("$script")
      printf 'set -euo pipefail\n' > "$script"
    fi
    continue
  fi
  if [[ $line =~ ^\`\`\` ]]; then
    in_block=false
    continue
  fi
  if ! $continued && builds "$line"; then
    printf '# README.md:%d, not run (it builds): %s\n' "$number" "$line" >> "$script"
    skipped=$((skipped + 1))
    [[ $line =~ \\$ ]] && echo "readme_commands: README.md:$number: a build line continues" >&2 &&
      exit 1
    continue
  fi
  # Each build/PRESET folder a command names (outside its comment) is this test's build.
  for preset in $presets; do
    if [[ ${line%%#*} =~ (^|[[:space:]=])build/$preset(/|[[:space:]]|$) ]] &&
      [ ! -e "$clone/build/$preset" ]; then
      mkdir -p "$clone/build"
      ln -s "$build_dir" "$clone/build/$preset"
    fi
  done
  if ! $continued && [[ $line =~ ^[[:space:]]*[^[:space:]#] ]]; then
    printf 'echo %q\n' "README.md:$number: $line" >> "$script"
  fi
  printf '%s\n' "$line" >> "$script"
  if [[ $line =~ \\$ ]]; then continued=true; else continued=false; fi
done < "$source_dir/README.md"

if [ ${#blocks[@]} = 0 ]; then
  echo "readme_commands: no \`\`\`sh blocks in $source_dir/README.md" >&2
  exit 1
fi
ran=0
for script in "${blocks[@]}"; do
  if ! grep -q '^echo ' "$script"; then
    continue  # a block of build lines only
  fi
  if ! (cd "$clone" && HOME=$work_dir/home bash "$script"); then
    echo "readme_commands: a command of the block at ${script##*/} failed" >&2
    exit 1
  fi
  ran=$((ran + $(grep -c '^echo ' "$script")))
done
echo "readme_commands: ${#blocks[@]} blocks, ${ran} commands run, all passed (${skipped} that build" \
  "not run)"
rm -rf "$work_dir"  # what they wrote (the frames of a run are megabytes)
