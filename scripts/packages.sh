# Sourced by scripts/setup.sh and scripts/fuzz.sh: install_packages TAG PACKAGE... installs the Debian packages
# that are not installed yet (apt-get, as root or through sudo), saying which on stderr; exits 1 when it cannot.
install_packages() {
  local tag="$1"
  shift
  local missing=() p status
  for p in "$@"; do
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "$tag: installing ${missing[*]}" >&2
  local sudo=""
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "$tag: not root and no sudo: install ${missing[*]} first" >&2; exit 1; }
    sudo="sudo"
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}
