# Starts `sleep 1000` in the background (same process group, same stdout) and tells its pid; hangs
# or dies of SIGSEGV when the request asks; exits at end of input, leaving the sleep behind.
# (sh, not Python: it must answer its first request well within a short time limit.)
sleep 1000 &
sleeper=$!
while read -r line; do
  id=${line##*\"id\":}
  id=${id%%[,\}]*}
  case $line in
    *'"hang":true'*) while :; do sleep 1000; done ;;
    *'"crash":true'*) kill -SEGV $$ ;;
  esac
  printf '{"id": %s, "grandchild": %s}\n' "$id" "$sleeper"
done
