# cmake -DPRELUDE=... -DFILE=... -P prepend.cmake: writes PRELUDE's text before FILE's.
file(READ ${PRELUDE} prelude)
file(READ ${FILE} body)
file(WRITE ${FILE} "${prelude}${body}")
