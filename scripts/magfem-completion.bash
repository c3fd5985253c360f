# bash completion for magfem: commands, each command's options and their values, case files.
# Installed as share/bash-completion/completions/magfem; from a source tree:
#   source scripts/magfem-completion.bash
_magfem() {
  local cur prev command
  cur="${COMP_WORDS[COMP_CWORD]}"
  prev="${COMP_WORDS[COMP_CWORD-1]}"
  command="${COMP_WORDS[1]}"
  local commands="solve mesh analytic compare sweep study optimize actuator materials validate help"

  if ((COMP_CWORD == 1)); then
    COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
    return
  fi
  case "$prev" in
    --out) COMPREPLY=($(compgen -d -- "$cur")); return ;;
    --order) COMPREPLY=($(compgen -W "1 2" -- "$cur")); return ;;
    --model) COMPREPLY=($(compgen -W "charge harmonic" -- "$cur")); return ;;
    --axis | --plane) COMPREPLY=($(compgen -W "x y z" -- "$cur")); return ;;
    --tier) COMPREPLY=($(compgen -W "quick full" -- "$cur")); return ;;
    --mesh-scale | --max-memory | --tolerance | --n-max | --rotate | --move | --angles | --positions | --point | --surface-radius | \
      --jobs | --only | --source | --param | --vary | --xtol | --rotor | --orientations | --torque | --coil-quadrature | --coil-pitch | --constraint | --accuracy | --max-passes | --max-unknowns) return ;;
    --export) COMPREPLY=($(compgen -W "steel_1010 steel_1018 M-19 pure_iron" -- "$cur")); return ;;
    --objective | --maximize | --minimize)
      COMPREPLY=($(compgen -W "peak_torque torque_at:" -- "$cur"))
      return
      ;;
  esac
  local options
  case "$command" in
    solve) options="--out --order --mesh-scale --max-memory --accuracy --max-passes --max-unknowns --param --quiet --help" ;;
    mesh) options="--out --order --mesh-scale --plane --param --help" ;;
    analytic) options="--out --model --tolerance --n-max --param --help" ;;
    compare) options="--help" ;;
    sweep) options="--rotate --move --axis --angles --positions --point --analytic --surface-radius --jobs --out --order --mesh-scale --max-memory --resume --quiet --help" ;;
    materials) options="--export --help" ;;
    validate) options="--tier --only --source --jobs --resume --catalogue --out --help" ;;
    study) options="--param --objective --rotate --axis --angles --analytic --fe --mesh-scale --order --accuracy --max-passes --max-unknowns --jobs --quiet --resume --out --help" ;;
    actuator) options="--rotor --orientations --torque --analytic --param --order --mesh-scale --coil-quadrature --verify --accuracy --max-passes --max-unknowns --quiet --out --coil-pitch --help" ;;
    optimize) options="--vary --maximize --minimize --rotate --axis --angles --constraint --xtol --verify-fe --mesh-scale --order --accuracy --max-passes --max-unknowns --quiet --out --help" ;;
    help) COMPREPLY=($(compgen -W "${commands% help}" -- "$cur")); return ;;
  esac
  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
    return
  fi
  case "$command" in
    compare) COMPREPLY=($(compgen -f -X '!*.csv' -- "$cur") $(compgen -d -- "$cur")) ;;
    solve | mesh | analytic | sweep | study | optimize | actuator) COMPREPLY=($(compgen -f -X '!*.yaml' -- "$cur") $(compgen -d -- "$cur")) ;;
  esac
}
complete -o filenames -F _magfem magfem
