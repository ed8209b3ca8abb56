# Leaves two sleeping processes that escape the program's process group: one started with setsid
# (its own session and group, a child of the program), one double-forked and setsid (its parent
# exits at once, so it is orphaned and comes to numlab, the child subreaper). Tells their pids, and
# writes a file in its working folder. Hangs when a request asks; exits at end of input.
setsid sleep 1000 &
escaped=$!
(setsid sleep 1000 & echo $! > orphan.pid)
orphan=$(cat orphan.pid)
while read -r line; do
  id=${line##*\"id\":}
  id=${id%%[,\}]*}
  case $line in
    *'"hang":true'*) while :; do sleep 1000; done ;;
  esac
  printf '{"id": %s, "escaped": %s, "orphan": %s}\n' "$id" "$escaped" "$orphan"
done
