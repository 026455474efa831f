# The test: passes when the answer is 42, after a delay of 0 seconds.
answer=42
delay=0
sleep $delay
[ "$answer" = 42 ]
