#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Stands in for espeak-ng in the announcer rostest: records when each utterance starts
# and ends (the text is the last argument) in $RF_ANNOUNCER_LOG.
for text; do :; done
echo "start $text" >> "$RF_ANNOUNCER_LOG"
sleep 0.4
echo "end $text" >> "$RF_ANNOUNCER_LOG"
