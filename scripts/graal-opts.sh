# shellcheck shell=bash
# Extra JVM flags for the ./kicnp launcher, sourced by it.
#
# graal_opts TARGET_DIR prints zero or more JVM flags, one per line, for running the module whose Maven
# target directory is TARGET_DIR (e.g. kicnp-cli/target, whose lib/ holds its runtime dependencies).
# It is the one place that decides how the JVM runs JavaScript fast (the Graal compiler for GraalJS);
# for now it prints nothing, so the JVM runs with its defaults.
graal_opts() {
    local target_dir="$1"
    : "$target_dir"
}
