#!/usr/bin/env bash
# Checks of the house (issue 43) that anyone can run: the largest source files, and that each
# rule written once is still written once. A rule is found by the distinctive name of its one
# definition (not by its formula); the script exits 1 when a rule is defined more or less than
# once. ctest runs it as `house_checks`.
# Usage: tools/house_checks.sh [source directory]
set -uo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root" || exit 2

# The source files: the library, its headers, the CLI, the Python and web bindings.
sources() {
    find src include apps python/src python/momentlab web/src web -maxdepth 3 -type f \
         \( -name '*.cpp' -o -name '*.hpp' -o -name '*.py' -o -name '*.js' -o -name '*.mjs' \) \
         -not -path '*/node_modules/*' 2>/dev/null | sort -u
}

echo "The 10 largest source files (lines):"
sources | xargs wc -l | grep -v ' total$' | sort -n | tail -10

# Lines of the source files matching an extended regular expression, comments left out.
defined() {
    sources | xargs grep -nE "$1" 2>/dev/null | grep -vE '^[^:]+:[0-9]+:[[:space:]]*(//|/\*|\*|#)'
}

status=0
check() {  # name, regex of its one definition
    local found count
    found=$(defined "$2")
    count=$(printf '%s' "$found" | grep -c .)
    printf '%-56s %s\n' "$1" "$count"
    if [[ $count -ne 1 ]]; then
        [[ -n $found ]] && printf '%s\n' "$found" | sed 's/^/    /'
        status=1
    fi
}

echo
echo "Each rule, the number of its definitions (must be 1):"
check "friction edge n + c t (friction_direction)" '\bfriction_direction\(const '
check "sliding friction opposes the slip (opposing_friction)" '\bopposing_friction\(ContactMode '
check "a contact's generators per letter (contact_generators)" '\bcontact_generators\(char '
check "inertia matrix at the origin (inertia_matrix)" '\binertia_matrix\(const '
check "angular order: the half of a direction (angular_half)" '\bangular_half\(Sign '
check "angular order: comparing two (angular_compare)" '\bangular_compare\(int '
check "the range message (kMagnitudeRange =)" '\bkMagnitudeRange = '
check "the range written as text (\"...1e-60...\")" '"[^"]*1e-60'
check "the underflow message (kTooSmallForADouble =)" '\bkTooSmallForADouble = '
check "the underflow written as text (\"...taken as 0...\")" '"[^"]*taken as 0'
check "text as shown to a user (printable)" '^std::string printable\(std::string_view '
exit $status
