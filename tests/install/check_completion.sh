#!/usr/bin/env bash
# The completion script parses, completes commands and per-command options, and offers the
# same commands as `magfem --help` (a command added to one and not the other fails here).
# Usage: check_completion.sh COMPLETION_SCRIPT MAGFEM
set -euo pipefail
script=$1
exe=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
bash -n "$script" || fail "syntax error in $script"
source "$script"

complete_words() { # words... -> the completions of the last word
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _magfem
  printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' '
}

offered=$(complete_words magfem "" | tr ' ' '\n' | grep -v '^-' | grep -v '^help$' | grep -v '^$' | sort | tr '\n' ' ')
listed=$("$exe" --help | sed -n '/^commands:/,/^$/p' | awk 'NF && !/commands:/ {print $1}' | sort | tr '\n' ' ')
[[ $offered == "$listed" ]] || fail "completion offers '$offered', magfem --help lists '$listed'"
[[ $(complete_words magfem so) == "solve " ]] || fail "'so' does not complete to solve"
[[ $(complete_words magfem validate --ti) == "--tier " ]] || fail "validate --ti"
[[ $(complete_words magfem validate --tier "") == "full quick " ]] || fail "--tier values"
[[ $(complete_words magfem analytic --model h) == "harmonic " ]] || fail "--model values"
# Each command's option table (what it parses) is what the completion offers (and --help),
# and every option in it appears on the command's help page.
for command in $listed; do
  options=$(complete_words magfem "$command" --)
  table=$("$exe" help --list-options "$command" | awk '{print $1}')
  expected=$(printf '%s\n' $table --help | sort -u | tr '\n' ' ')
  [[ $options == "$expected" ]] || fail "$command: completion offers '$options', its option table '$expected'"
  page=$("$exe" help "$command")
  for option in $table; do
    grep -q -- "$option\b" <<<"$page" || fail "$command: help page lacks $option"
  done
done
echo "completion: ok ($listed)"
