#!/bin/bash
# queue.sh FILE: run the cases of FILE (lines "name|gen_deck options") one after the other.
while IFS='|' read -r name opts; do
  [ -z "$name" ] && continue
  ./run_case.sh "$name" $opts
done < "$1"
