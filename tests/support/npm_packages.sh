# Sourced by the test scripts that check tessera's output with third-party readers and clients
# from npm (tests/io/mcap_thirdparty, tests/record, tests/live).
#   skip REASON: exit 77 (ctest's SKIP_RETURN_CODE), or fail with CI=true, where every check must
#     run.
#   npm_packages DIR PACKAGE@VERSION...: installs the packages into DIR (outside the source tree)
#     unless they are there; sets NODE_PATH to DIR/node_modules. Skips without node and npm or
#     when the registry cannot be reached.

skip() {
  if [ "${CI:-}" = "true" ]; then
    echo "FAIL: $1 (CI=true: the check must run)"
    exit 1
  fi
  echo "SKIP: $1"
  exit 77
}

npm_packages() {
  local dir=$1 p missing=0
  shift
  command -v node >/dev/null && command -v npm >/dev/null || skip "node and npm are not installed"
  for p in "$@"; do
    [ -f "$dir/node_modules/${p%@*}/package.json" ] || missing=1
  done
  if [ $missing -eq 1 ]; then
    mkdir -p "$dir"
    [ -f "$dir/package.json" ] || echo '{"name":"tessera-thirdparty-check","private":true}' > "$dir/package.json"
    (cd "$dir" && PUPPETEER_SKIP_DOWNLOAD=1 timeout 300 npm install --no-audit --no-fund --silent "$@") ||
      skip "npm install $* failed (registry unreachable?)"
    for p in "$@"; do
      [ -f "$dir/node_modules/${p%@*}/package.json" ] || skip "npm install left ${p%@*} out"
    done
  fi
  export NODE_PATH="$dir/node_modules"
}
