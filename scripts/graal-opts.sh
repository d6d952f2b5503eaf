# shellcheck shell=bash
# Sourced by ./kicnp (not executed). Defines graal_opts, which prints the JVM flags that let GraalJS compile
# scripts with the Graal JIT on a stock JDK, for the module whose target/ directory is given. It prints
# nothing when the jars are missing (the module was not packaged, or does not use GraalJS), when
# KICNP_GRAAL=off, or when the JDK has no JVMCI; the JVM then runs scripts interpreter-only, which is slower
# but correct. See docs/scripting.md.
#
# The jars are copied, without versions in their names, by the maven-dependency-plugin at `package`:
#   <target>/graal/compiler/compiler.jar     the Graal compiler: replaces the JDK's jdk.graal.compiler module,
#                                            hence --upgrade-module-path
#   <target>/graal/modules/*.jar             polyglot, Truffle (api, runtime, compiler), GraalJS and their
#                                            sdk/shadowed dependencies: on the module path, so the Truffle
#                                            runtime is a named module that may open JVMCI
# Application classes stay on the class path; copies of the same jars there are harmless (named modules win).
#
# It prints one flag per line, so paths may contain spaces when read into an array:
#   mapfile -t opts < <(graal_opts kicnp-cli/target); java "${opts[@]}" -cp "$CP" org.kicnp.cli.Main ...
# ($(graal_opts ...) unquoted also works when the paths have no spaces).

graal_opts() {
    local target="${1:?usage: graal_opts <module-target-dir>}"
    if [[ "${KICNP_GRAAL:-on}" == "off" ]]; then
        return 0
    fi
    local compiler="$target/graal/compiler/compiler.jar"
    if [[ ! -f "$compiler" || ! -d "$target/graal/modules" ]]; then
        return 0
    fi
    local modules
    modules=$( (find "$target/graal/modules" -maxdepth 1 -name '*.jar' | sort | paste -sd: -) 2>/dev/null || true)
    if [[ "$modules" != */polyglot.jar* || "$modules" != */truffle-runtime.jar* || "$modules" != */truffle-compiler.jar* ]]; then
        return 0
    fi
    # -XX:+EnableJVMCI is fatal on a JDK without JVMCI; the JDK's release file lists its modules.
    local home="${JAVA_HOME:-}"
    if [[ -z "$home" ]] && command -v java >/dev/null 2>&1; then
        home=$(dirname "$(dirname "$(readlink -f "$(command -v java)")")")
    fi
    if ! grep -q 'jdk\.internal\.vm\.ci' "$home/release" 2>/dev/null; then
        return 0
    fi
    printf '%s\n' -XX:+UnlockExperimentalVMOptions -XX:+EnableJVMCI "--upgrade-module-path=$compiler" \
        "--module-path=$modules" --add-modules=ALL-MODULE-PATH --enable-native-access=ALL-UNNAMED,org.graalvm.truffle
}
