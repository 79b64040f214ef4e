<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>CoreMessage</name>
    <message>
        <location filename="core_messages.cpp" line="+12"/>
        <source>%s refused: %s</source>
        <translation>%s abgelehnt: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run %u ended: %s (%ld samples)</source>
        <translation>Lauf %u beendet: %s (%ld Abtastwerte)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Emergency stop (%s, from %s): %s off, drives %s</source>
        <translation>NOT-HALT (%s, aus %s): %s aus, Antriebe %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>disabled</source>
        <translation>abgeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopping along the path, then disabled</source>
        <translation>halten auf der Bahn an, dann abgeschaltet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fault: %s (controlled stop cut short: drives disabled)</source>
        <translation>Störung: %s (geführter Halt abgebrochen: Antriebe abgeschaltet)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fault: %s</source>
        <translation>Störung: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fault: %.110s</source>
        <translation>Störung: %.110s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fault: %s; %s off, %s stop</source>
        <translation>Störung: %s; %s aus, Halt %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%.1f deg/s, %.1f mm/s</source>
        <translation>%.1f °/s, %.1f mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%.1f mm/s</source>
        <translation>%.1f mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%.1f deg/s</source>
        <translation>%.1f °/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s: %.3f s move at up to %s</source>
        <translation>%s: Bewegung von %.3f s mit höchstens %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Homing to the reference</source>
        <translation>Referenzfahrt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jogging</source>
        <translation>Tippen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Approach to the start position</source>
        <translation>Anfahrt der Startposition</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Approach to the first cut point</source>
        <translation>Anfahrt des ersten Schnittpunkts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run %u started: %s, cut recovery from path time %.3f s (point %u of %zu, %.1f of %.1f mm)</source>
        <translation>Lauf %u gestartet: %s, Wiederaufnahme ab Bahnzeit %.3f s (Punkt %u von %zu, %.1f von %.1f mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run %u started: %s, %.1f mm in %.2f s</source>
        <translation>Lauf %u gestartet: %s, %.1f mm in %.2f s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start: control law</source>
        <translation>Start: Regelgesetz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start: approach to the recovery point</source>
        <translation>Start: Anfahrt des Wiederaufnahmepunkts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start: approach to the first cut point</source>
        <translation>Start: Anfahrt des ersten Schnittpunkts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a motion is in progress (%s)</source>
        <translation>eine Bewegung läuft (%s)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no program</source>
        <translation>kein Programm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis_count = %d is outside 1 .. %d</source>
        <translation>axis_count = %d liegt außerhalb 1 .. %d</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the program has no trajectory</source>
        <translation>das Programm hat keine Bahn</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the %s program has no motion source</source>
        <translation>das Programm (%s) hat keine Bewegungsquelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sensor %zu is used by the program but not connected</source>
        <translation>Sensor %zu wird vom Programm benutzt, ist aber nicht angeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s) has no drive</source>
        <translation>Achse %d (%s) hat keinen Antrieb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s): the program commands %s, the drive is set to %s (set the mode before the run)</source>
        <translation>Achse %d (%s): das Programm gibt %s vor, der Antrieb steht auf %s (Betriebsart vor dem Lauf einstellen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reference of axis %d = %.4g is outside %.4g .. %.4g</source>
        <translation>Referenz der Achse %d = %.4g liegt außerhalb %.4g .. %.4g</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%zu points, %.1f mm</source>
        <translation>%zu Punkte, %.1f mm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>drives already enabled (%s)</source>
        <translation>Antriebe bereits freigegeben (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no job loaded</source>
        <translation>kein Auftrag geladen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drives are already enabling</source>
        <translation>Antriebe werden bereits freigegeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enabling drives</source>
        <translation>Antriebe werden freigegeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drives already disabled (%s)</source>
        <translation>Antriebe bereits abgeschaltet (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>motion in progress (%s): Abort first</source>
        <translation>Bewegung läuft (%s): zuerst Abbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drives are not enabled</source>
        <translation>Antriebe sind nicht freigegeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enable cancelled: drives disabled</source>
        <translation>Freigabe abgebrochen: Antriebe abgeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drives disabled</source>
        <translation>Antriebe abgeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drives not enabled</source>
        <translation>Antriebe nicht freigegeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>already homing</source>
        <translation>Referenzfahrt läuft bereits</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>motion in progress (%s)</source>
        <translation>Bewegung läuft (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>only while Ready (state %s)</source>
        <translation>nur im Zustand Bereit (Zustand %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d does not exist (0 .. %d)</source>
        <translation>Achse %d gibt es nicht (0 .. %d)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the jog distance is not a number</source>
        <translation>der Tippweg ist keine Zahl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s) target %.3f %s is outside its range %.3f .. %.3f %s</source>
        <translation>Achse %d (%s): Ziel %.3f %s liegt außerhalb ihres Bereichs %.3f .. %.3f %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>already running</source>
        <translation>läuft bereits</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>paused (use Resume)</source>
        <translation>angehalten (Fortsetzen benutzen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the cut is complete (Home, then Start)</source>
        <translation>der Schnitt ist fertig (Referenz, dann Start)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not homed (Home first)</source>
        <translation>nicht referenziert (zuerst Referenz)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut recovery needs a path in time; this machine&apos;s motion follows a %s source</source>
        <translation>die Wiederaufnahme braucht eine Bahn in der Zeit; die Bewegung dieser Maschine folgt einer Quelle %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recovery from path time %.3f s is outside the cut (0 .. %.3f s)</source>
        <translation>Wiederaufnahme ab Bahnzeit %.3f s liegt außerhalb des Schnitts (0 .. %.3f s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not running (state %s)</source>
        <translation>läuft nicht (Zustand %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a stop is in progress</source>
        <translation>ein Halt läuft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>already holding</source>
        <translation>Vorschub hält bereits</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Feed hold: %s (%s)</source>
        <translation>Vorschub halt: %s (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>finishing the cut, returning, then no more waiting for the line</source>
        <translation>Schnitt wird beendet, Rückfahrt, dann kein Warten mehr auf die Linie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the control law brings the axes to rest</source>
        <translation>das Regelgesetz bringt die Achsen zur Ruhe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Feed hold: decelerating along the path (%s %s)</source>
        <translation>Vorschub halt: Verzögerung auf der Bahn (%s %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stays on</source>
        <translation>bleibt an</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resume at path time %.3f s</source>
        <translation>Fortsetzen bei Bahnzeit %.3f s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resume while decelerating: back to speed</source>
        <translation>Fortsetzen während der Verzögerung: zurück auf Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not paused (state %s)</source>
        <translation>nicht angehalten (Zustand %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%.0f %% is outside 10 .. 150 %%</source>
        <translation>%.0f %% liegt außerhalb 10 .. 150 %%</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Override %.0f %%</source>
        <translation>Override %.0f %%</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing to abort (state %s)</source>
        <translation>nichts abzubrechen (Zustand %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>already aborting</source>
        <translation>Abbruch läuft bereits</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort: %s off, stopping along the path</source>
        <translation>Abbruch: %s aus, Halt auf der Bahn</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Emergency stop pressed again: already latched</source>
        <translation>NOT-HALT erneut gedrückt: bereits verriegelt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the emergency stop is not pressed</source>
        <translation>der NOT-HALT ist nicht gedrückt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Emergency stop released (Reset to clear)</source>
        <translation>NOT-HALT entriegelt (Reset zum Quittieren)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing to reset (state %s)</source>
        <translation>nichts zurückzusetzen (Zustand %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the emergency stop is still pressed (release it first)</source>
        <translation>der NOT-HALT ist noch gedrückt (zuerst entriegeln)</translation>
    </message>
    <message>
        <location line="-57"/>
        <source>the controlled stop is still in progress</source>
        <translation>der geführte Halt läuft noch</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Reset: %s cleared, drives disabled</source>
        <translation>Reset: %s quittiert, Antriebe abgeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <location line="-78"/>
        <source>emergency stop</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%zu points</source>
        <translation>%zu Punkte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%zu pieces, %.1f mm in all</source>
        <translation>%zu Stück, %.1f mm insgesamt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%zu strokes</source>
        <translation>%zu Hübe</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>emergency stop latched (release it, then Reset)</source>
        <translation>NOT-HALT verriegelt (entriegeln, dann Reset)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fault latched (Reset first)</source>
        <translation>Störung verriegelt (zuerst Reset)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run log: %s</source>
        <translation>Laufprotokoll: %s</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Emergency stop complete: drives disabled, %s off, %.0f us after the request</source>
        <translation>NOT-HALT ausgeführt: Antriebe abgeschaltet, %s aus, %.0f µs nach der Anforderung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enable failed: axis %d (%s) reports drive fault 0x%04X</source>
        <translation>Freigabe fehlgeschlagen: Achse %d (%s) meldet Antriebsfehler 0x%04X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enable failed: axis %d (%s) is still %s after %.2f s</source>
        <translation>Freigabe fehlgeschlagen: Achse %d (%s) ist noch %s nach %.2f s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drives enabled</source>
        <translation>Antriebe freigegeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drives enabled (not homed: Home before Start)</source>
        <translation>Antriebe freigegeben (nicht referenziert: Referenz vor Start)</translation>
    </message>
    <message>
        <location line="-27"/>
        <source>Aborted: stopped on the path at %.3f s</source>
        <translation>Abgebrochen: auf der Bahn angehalten bei %.3f s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controlled stop complete: drives disabled</source>
        <translation>Geführter Halt ausgeführt: Antriebe abgeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Homed: at the reference</source>
        <translation>Referenziert: an der Referenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog done</source>
        <translation>Tippen fertig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Paused on the path at %.3f s (%s %s)</source>
        <translation>Auf der Bahn angehalten bei %.3f s (%s %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>At the first cut point after %.3f s of settling: %s on</source>
        <translation>Am ersten Schnittpunkt nach %.3f s Einschwingen: %s an</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start failed: the axes did not settle within %.4g of the first cut point in %.1f s</source>
        <translation>Start fehlgeschlagen: die Achsen kamen nicht innerhalb %.4g um den ersten Schnittpunkt zur Ruhe in %.1f s</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%s: %s program running</source>
        <translation>%s: Programm (%s) läuft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s: %s program resumed</source>
        <translation>%s: Programm (%s) fortgesetzt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Process OK</source>
        <translation>Prozess in Ordnung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>Arc established: piercing for %.3f s</source>
        <translation>Lichtbogen steht: Einstechen für %.3f s</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Arc established: cutting</source>
        <translation>Lichtbogen steht: Schneiden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Arc established: resuming the cut</source>
        <translation>Lichtbogen steht: Schnitt wird fortgesetzt</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>%s: %s not reported within %.1f s</source>
        <translation>%s: %s nicht gemeldet innerhalb %.1f s</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Pierced: cutting</source>
        <translation>Eingestochen: Schneiden</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Program finished (%s, %u of %u %s): %s off</source>
        <translation>Programm beendet (%s, %u von %u %s): %s aus</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Cut finished at path time %.3f s: %s off</source>
        <translation>Schnitt beendet bei Bahnzeit %.3f s: %s aus</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Completed: %.1f of %.1f mm in %.2f s (cut recovery from point %u of %u: the %.1f mm before it were not cut by this run)</source>
        <translation>Beendet: %.1f von %.1f mm in %.2f s (Wiederaufnahme ab Punkt %u von %u: die %.1f mm davor hat dieser Lauf nicht geschnitten)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Completed: %.1f mm in %.2f s</source>
        <translation>Beendet: %.1f mm in %.2f s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Completed: %u %s in %.2f s</source>
        <translation>Beendet: %u %s in %.2f s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>completed</source>
        <translation>beendet</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%s source (%s): %s</source>
        <translation>Quelle %s (%s): %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s): drive fault 0x%04X at %.3f %s (set-point %.3f %s)</source>
        <translation>Achse %d (%s): Antriebsfehler 0x%04X bei %.3f %s (Sollwert %.3f %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s): drive left operation (now %s)</source>
        <translation>Achse %d (%s): Antrieb hat den Betrieb verlassen (jetzt %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s): feedback not valid (stale data) at %.3f %s</source>
        <translation>Achse %d (%s): Rückmeldung ungültig (veraltete Daten) bei %.3f %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s): following-error supervision on again (further changes in this run are not logged)</source>
        <translation>Achse %d (%s): Schleppfehlerüberwachung wieder an (weitere Wechsel in diesem Lauf werden nicht protokolliert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s): following-error supervision off: %s</source>
        <translation>Achse %d (%s): Schleppfehlerüberwachung aus: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s): feedback frozen at %.4f %s while the set-point moved %.4f %s</source>
        <translation>Achse %d (%s): Rückmeldung steht bei %.4f %s, während sich der Sollwert um %.4f %s bewegte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %d (%s): following error %.3f %s exceeds %.3f %s (set-point %.3f %s, actual %.3f %s, feedback %u cycle(s) late)</source>
        <translation>Achse %d (%s): Schleppfehler %.3f %s überschreitet %.3f %s (Sollwert %.3f %s, Istwert %.3f %s, Rückmeldung %u Zyklus/Zyklen verspätet)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s: fault 0x%04X</source>
        <translation>%s: Fehler 0x%04X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s: %s (%s, %s %u of %u)</source>
        <translation>%s: %s (%s, %s %u von %u)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s: %s at point %u of %zu (path time %.3f s)</source>
        <translation>%s: %s bei Punkt %u von %zu (Bahnzeit %.3f s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load</source>
        <translation>Laden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enable</source>
        <translation>Freigeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disable</source>
        <translation>Abschalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog</source>
        <translation>Tippen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Feed hold</source>
        <translation>Vorschub halt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Override</source>
        <translation>Override</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort</source>
        <translation>Abbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Emergency stop</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Release emergency stop</source>
        <translation>NOT-HALT entriegeln</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disabled</source>
        <translation>abgeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enabling</source>
        <translation>wird freigegeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enabled</source>
        <translation>freigegeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>QuickStop</source>
        <translation>Schnellhalt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position (CSP)</source>
        <translation>Position (CSP)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>velocity (CSV)</source>
        <translation>Geschwindigkeit (CSV)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torque (CST)</source>
        <translation>Drehmoment (CST)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>joint spline</source>
        <translation>Gelenk-Spline</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>master axis</source>
        <translation>Leitachse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>control law</source>
        <translation>Regelgesetz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>waiting</source>
        <translation>wartet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>synchronizing</source>
        <translation>synchronisiert sich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>in sync</source>
        <translation>synchron</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>returning</source>
        <translation>Rückfahrt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopping</source>
        <translation>hält an</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>done</source>
        <translation>fertig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>master encoder: reading not valid</source>
        <translation>Leitgeber: Messwert ungültig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the master is already past the start of the sync-in</source>
        <translation>der Leitwert ist schon über den Beginn der Einsynchronisierung hinaus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>master passed the sync position before synchronizing</source>
        <translation>der Leitwert passierte die Synchronposition vor dem Einsynchronisieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tracking</source>
        <translation>Folgen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cutting stroke</source>
        <translation>Schnitthub</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>open-loop return</source>
        <translation>gesteuerter Rückhub</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>catching</source>
        <translation>Abfangen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>braking</source>
        <translation>Bremsen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>slider position sensor: reading not valid</source>
        <translation>Schieber-Positionssensor: Messwert ungültig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>open-loop torque return stroke</source>
        <translation>gesteuerter Rückhub mit Drehmoment</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>catching the slider after the open-loop return</source>
        <translation>Abfangen des Schiebers nach dem gesteuerten Rückhub</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Real-time: normal scheduler (no SCHED_FIFO asked)</source>
        <translation>Echtzeit: normaler Scheduler (kein SCHED_FIFO verlangt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Real-time: SCHED_FIFO %d granted</source>
        <translation>Echtzeit: SCHED_FIFO %d gewährt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Real-time: SCHED_FIFO %d NOT granted (%s: needs CAP_SYS_NICE or an rtprio limit, so jitter follows the normal scheduler)</source>
        <translation>Echtzeit: SCHED_FIFO %d nicht gewährt (%s: braucht CAP_SYS_NICE oder ein rtprio-Limit, daher folgt der Jitter dem normalen Scheduler)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>memory not locked (not asked)</source>
        <translation>Speicher nicht gesperrt (nicht verlangt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>memory locked</source>
        <translation>Speicher gesperrt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>memory NOT locked (%s)</source>
        <translation>Speicher nicht gesperrt (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sanitizer build</source>
        <translation>Sanitizer-Build</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pinned to CPU %d</source>
        <translation>an CPU %d gebunden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NOT pinned to CPU %d (%s)</source>
        <translation>nicht an CPU %d gebunden (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>/dev/cpu_dma_latency held at 0 us</source>
        <translation>/dev/cpu_dma_latency auf 0 µs gehalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>/dev/cpu_dma_latency NOT held (%s)</source>
        <translation>/dev/cpu_dma_latency nicht gehalten (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>piece</source>
        <translation>Stück</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stroke</source>
        <translation>Hub</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pierces</source>
        <translation>Einstiche</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pieces</source>
        <translation>Stück</translation>
    </message>
    <message>
        <location line="-144"/>
        <source>Job loaded: %s (%s, %.2f s)</source>
        <translation>Auftrag geladen: %s (%s, %.2f s)</translation>
    </message>
    <message>
        <location line="-36"/>
        <source>%s off after %.3f s, %.1f mm</source>
        <translation>%s aus nach %.3f s, %.1f mm</translation>
    </message>
    <message>
        <location line="+181"/>
        <source>strokes</source>
        <translation>Hübe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torch</source>
        <translation>Brenner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc established</source>
        <translation>Lichtbogen steht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc lost</source>
        <translation>Lichtbogen verloren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s = %.6g %s is not a finite number</source>
        <translation>%s = %.6g %s ist keine endliche Zahl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s = %.6g %s is outside [%.6g, %.6g] %s</source>
        <translation>%s = %.6g %s liegt außerhalb von [%.6g, %.6g] %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cat0</source>
        <translation>Kat. 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cat1</source>
        <translation>Kat. 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s = %.6g %s: axis %d (%s) travels to %.6g %s, %.4g counts, beyond a drive&apos;s 32-bit position (%.0f counts); at most %.6g %s</source>
        <translation>%s = %.6g %s: Achse %d (%s) fährt bis %.6g %s, %.4g Inkremente, jenseits der 32-Bit-Position eines Antriebs (%.0f Inkremente); höchstens %.6g %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>devices.bitrate_bps = %d bit/s is not a CAN bit rate: one of 10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000 bit/s</source>
        <translation>devices.bitrate_bps = %d bit/s ist keine CAN-Bitrate: eine von 10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000 bit/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>devices.node_ids[%d] = %d is outside [1, 127]</source>
        <translation>devices.node_ids[%d] = %d liegt außerhalb von [1, 127]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>devices.node_ids[%d] = %d is used twice</source>
        <translation>devices.node_ids[%d] = %d ist doppelt vergeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>devices.sensor_node_ids[%d] = %d is outside [1, 127]</source>
        <translation>devices.sensor_node_ids[%d] = %d liegt außerhalb von [1, 127]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>devices.sensor_node_ids[%d] = %d is the node of axis %d (devices.node_ids[%d])</source>
        <translation>devices.sensor_node_ids[%d] = %d ist der Knoten der Achse %d (devices.node_ids[%d])</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>devices.sensor_node_ids[%d] = %d is used twice</source>
        <translation>devices.sensor_node_ids[%d] = %d ist doppelt vergeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>devices.sync_counter_overflow = 1 is reserved (CiA 301 0x1019): 0 for no SYNC counter, or 2..240</source>
        <translation>devices.sync_counter_overflow = 1 ist reserviert (CiA 301 0x1019): 0 für SYNC ohne Zähler, oder 2..240</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>machine.kind = %s is not one of %s</source>
        <translation>machine.kind = %s ist keine von %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>devices.kind = &quot;canopen&quot;: %s</source>
        <translation>devices.kind = &quot;canopen&quot;: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s = %.6g counts/%s: axis %d (%s) goes as far as %.6g %s in this run, %.4g counts, beyond a drive&apos;s 32-bit position (%.0f counts); at most %.6g counts/%s, or a shorter run</source>
        <translation>%s = %.6g Imp./%s: Achse %d (%s) kommt in diesem Lauf bis %.6g %s, %.4g Impulse, über die 32-Bit-Position eines Antriebs hinaus (%.0f Impulse); höchstens %.6g Imp./%s, oder ein kürzerer Lauf</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s.wall_mm = %.6g mm must be less than %s.radius_mm = %.6g mm</source>
        <translation>%s.wall_mm = %.6g mm muss kleiner sein als %s.radius_mm = %.6g mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>angle_deg = %.6g deg is outside [0.1, 90] deg (angle between the pipe axes)</source>
        <translation>angle_deg = %.6g deg liegt außerhalb von [0,1, 90] deg (Winkel zwischen den Rohrachsen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>branch_pipe.radius_mm = %.6g mm does not fit: |eccentricity_mm| + branch radius = %.6g mm must be &lt;= main_pipe.radius_mm = %.6g mm</source>
        <translation>branch_pipe.radius_mm = %.6g mm passt nicht: |eccentricity_mm| + Abzweigradius = %.6g mm muss &lt;= main_pipe.radius_mm = %.6g mm sein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut.speed_mm_s = %.6g mm/s: the cut around the branch (about %.6g mm) would take %.6g s, longer than the limit of %.6g s (one hour)</source>
        <translation>cut.speed_mm_s = %.6g mm/s: der Schnitt um den Abzweig (etwa %.6g mm) dauerte %.6g s, länger als die Grenze von %.6g s (eine Stunde)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut.speed_mm_s = %.6g mm/s: the cut (up to %.6g mm, %.6g s) would need %.6g samples at sim.period_s = %.6g s; the limit is %.6g</source>
        <translation>cut.speed_mm_s = %.6g mm/s: der Schnitt (bis %.6g mm, %.6g s) bräuchte %.6g Abtastwerte bei sim.period_s = %.6g s; die Grenze ist %.6g</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>main_pipe.length_mm = %.6g mm is shorter than the cut along it (%.6g mm for a branch of radius %.6g mm at %.6g deg): the pipe must contain the cut</source>
        <translation>main_pipe.length_mm = %.6g mm ist kürzer als der Schnitt entlang des Rohrs (%.6g mm für einen Abzweig mit Radius %.6g mm unter %.6g deg): das Rohr muss den Schnitt enthalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>branch_pipe.length_mm = %.6g mm is shorter than the saddle of its cut end (%.6g mm): the pipe must contain the cut</source>
        <translation>branch_pipe.length_mm = %.6g mm ist kürzer als der Sattel seines Schnittendes (%.6g mm): das Rohr muss den Schnitt enthalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not feasible: machine.%s</source>
        <translation>nicht ausführbar: machine.%s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%d pieces at %.4g m/min; cycle %.2f s (sync-in %.3f s, sync + cut %.3f s, decel %.3f s, return %.3f s at k = %.2f); stroke %.0f of %.0f mm; shortest piece %.0f mm</source>
        <translation>%d Stücke bei %.4g m/min; Zyklus %.2f s (Einsynchronisieren %.3f s, Synchronlauf + Schnitt %.3f s, Bremsen %.3f s, Rücklauf %.3f s bei k = %.2f); Hub %.0f von %.0f mm; kürzestes Stück %.0f mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NOT completed: %s</source>
        <translation>NICHT abgeschlossen: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line encoder</source>
        <translation>Liniengeber</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>carriage.max_speed_mm_s = %.6g mm/s cannot reach the line: line.speed_m_min = %.6g m/min is up to %.6g mm/s with the line&apos;s wander and steps; the carriage needs &gt;= %.6g mm/s</source>
        <translation>carriage.max_speed_mm_s = %.6g mm/s erreicht die Linie nicht: line.speed_m_min = %.6g m/min sind mit Schwankung und Sprüngen der Linie bis %.6g mm/s; der Wagen braucht &gt;= %.6g mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>carriage.stroke_mm = %.6g mm is too short: sync-in %.6g mm + sync and cut %.6g mm (%.6g s at up to %.6g mm/s) + deceleration %.6g mm need %.6g mm from the wait position %.6g mm</source>
        <translation>carriage.stroke_mm = %.6g mm ist zu kurz: Einsynchronisieren %.6g mm + Gleichlauf und Schnitt %.6g mm (%.6g s bei bis %.6g mm/s) + Verzögerung %.6g mm brauchen %.6g mm ab der Warteposition %.6g mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut.queue[%zu].length_mm = %.6g mm is too short for the cycle at %.6g m/min (up to %.6g mm/s): the shortest possible is %.6g mm (sync-in %.6g mm, sync and cut %.6g s, deceleration %.6g mm, return %.6g s)</source>
        <translation>cut.queue[%zu].length_mm = %.6g mm ist zu kurz für den Zyklus bei %.6g m/min (bis %.6g mm/s): am kürzesten möglich sind %.6g mm (Einsynchronisieren %.6g mm, Gleichlauf und Schnitt %.6g s, Verzögerung %.6g mm, Rückfahrt %.6g s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>saw</source>
        <translation>Säge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>blade at speed</source>
        <translation>Sägeblatt auf Drehzahl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>blade speed lost</source>
        <translation>Sägeblattdrehzahl verloren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>saw.overcut_mm = %s mm leaves no wall: the wall (machine.tube.wall_mm = %s mm) and the overcut must fit in half the tube&apos;s width (%s mm); overcut at most %s mm</source>
        <translation>saw.overcut_mm = %s mm lässt keine Wand übrig: Wand (machine.tube.wall_mm = %s mm) und Überschnitt müssen in die halbe Rohrbreite passen (%s mm); Überschnitt höchstens %s mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut.queue is empty: at least one length is needed</source>
        <translation>cut.queue ist leer: mindestens eine Länge ist nötig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>decelerating</source>
        <translation>verzögert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recovering</source>
        <translation>Wiederaufnahme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line encoder: reading not valid</source>
        <translation>Liniengeber: Messwert ungültig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the line is already past the sync-in of the first cut</source>
        <translation>die Linie ist schon über die Einsynchronisierung des ersten Schnitts hinaus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the line passed the sync position before the carriage started</source>
        <translation>die Linie passierte die Synchronposition, bevor der Wagen anfuhr</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the piece is too short for the cycle at this line speed: the next sync-in has begun before the carriage was back</source>
        <translation>das Stück ist für den Zyklus bei dieser Liniengeschwindigkeit zu kurz: die nächste Einsynchronisierung begann, bevor der Wagen zurück war</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the wall + overcut (%.6g mm) leaves no bore in a tube of %.6g x %.6g mm</source>
        <translation>Wand + Überschnitt (%.6g mm) lassen keine Bohrung in einem Rohr von %.6g x %.6g mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>saw.table_points = %d is outside [8, %d]</source>
        <translation>saw.table_points = %d liegt außerhalb von [8, %d]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped at the simulation&apos;s bound of %.0f s of line time with %d of %d pieces made</source>
        <translation>an der Grenze der Simulation von %.0f s Linienzeit angehalten, %d von %d Stücken gefertigt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the queue of %d pieces needs about %.0f s of line time (%.3g cycles at %.3g ms), over the simulation&apos;s bound of %.0f s: split it (about %d pieces of this queue&apos;s mean length fit)</source>
        <translation>die Warteschlange von %d Stücken braucht etwa %.0f s Linienzeit (%.3g Zyklen bei %.3g ms), über der Grenze der Simulation von %.0f s: aufteilen (etwa %d Stücke der mittleren Länge dieser Warteschlange passen)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>path not reachable</source>
        <translation>Bahn nicht erreichbar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>out of reach: the wrist is %.3f mm beyond the arm&apos;s reach (joint 3)</source>
        <translation>außer Reichweite: das Handgelenk liegt %.3f mm jenseits der Reichweite des Arms (Gelenk 3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>joint %d = %.3f deg is past its limit %.3f deg by %.3f deg</source>
        <translation>Gelenk %d = %.3f deg überschreitet seine Grenze %.3f deg um %.3f deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>singular at joint %d (its angle is undefined here)</source>
        <translation>singulär bei Gelenk %d (sein Winkel ist hier unbestimmt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torch axis is %.3f deg off the plane of joint 1 (a 5-DOF arm can only tilt its torch within that plane)</source>
        <translation>die Brennerachse liegt %.3f deg außerhalb der Ebene von Gelenk 1 (ein 5-achsiger Arm kann seinen Brenner nur in dieser Ebene neigen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the inertia tensor has a negative principal moment %.6g kg cm^2</source>
        <translation>der Trägheitstensor hat ein negatives Hauptträgheitsmoment %.6g kg cm^2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the principal moments %.6g, %.6g, %.6g kg cm^2 break the triangle inequality (the largest may be at most the sum of the others)</source>
        <translation>die Hauptträgheitsmomente %.6g, %.6g, %.6g kg cm^2 verletzen die Dreiecksungleichung (das größte darf höchstens die Summe der anderen sein)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>robot.dh[%d].min_deg = %.6g deg must be below robot.dh[%d].max_deg = %.6g deg</source>
        <translation>robot.dh[%d].min_deg = %.6g deg muss unter robot.dh[%d].max_deg = %.6g deg liegen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>robot.dh[%d].min_deg = %.6g deg: the axis&apos;s range must hold its reference 0 deg (at most 0 deg)</source>
        <translation>robot.dh[%d].min_deg = %.6g deg: der Bereich der Achse muss ihre Referenz 0 deg enthalten (höchstens 0 deg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>robot.dh[%d].max_deg = %.6g deg: the axis&apos;s range must hold its reference 0 deg (at least 0 deg)</source>
        <translation>robot.dh[%d].max_deg = %.6g deg: der Bereich der Achse muss ihre Referenz 0 deg enthalten (mindestens 0 deg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>robot.dh[%d].alpha_deg = %.6g deg: the pipe robot&apos;s inverse kinematics needs %.6g deg</source>
        <translation>robot.dh[%d].alpha_deg = %.6g deg: die inverse Kinematik des Rohrroboters braucht %.6g deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>robot.dh[%d].%s = %.6g mm: the pipe robot&apos;s inverse kinematics needs 0 mm</source>
        <translation>robot.dh[%d].%s = %.6g mm: die inverse Kinematik des Rohrroboters braucht 0 mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>robot.dh[2].a_mm and robot.dh[3].a_mm must be &gt; 0 mm (arm links)</source>
        <translation>robot.dh[2].a_mm und robot.dh[3].a_mm müssen &gt; 0 mm sein (Armglieder)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>robot.links[%zu] (link %zu): %s</source>
        <translation>robot.links[%zu] (Glied %zu): %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>robot.chuck.inertia_kg_m2 = %.6g kg m^2: the chuck axis has no inertia (chuck, pipe and rotor sum to 0)</source>
        <translation>robot.chuck.inertia_kg_m2 = %.6g kg m^2: die Futterachse hat keine Trägheit (Futter, Rohr und Rotor ergeben zusammen 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>controller[%d].tau_f_s = %.6g s must be &gt;= half the control period (%.6g s)</source>
        <translation>controller[%d].tau_f_s = %.6g s muss &gt;= der halben Regelperiode sein (%.6g s)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the cut has fewer than 3 points</source>
        <translation>der Schnitt hat weniger als 3 Punkte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lead_in</source>
        <translation>lead_in</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lead_out</source>
        <translation>lead_out</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>process.%s.length_mm = %.6g mm is too long for the %s: the %s would reach the part&apos;s edge [it must stay half the kerf, %.6g mm, off it on the scrap side]; the longest that fits is %.3f mm</source>
        <translation>process.%s.length_mm = %.6g mm ist zu lang für %s: %s würde die Kante des Werkstücks erreichen [sie muss die halbe Schnittfuge, %.6g mm, auf der Restseite davon bleiben]; am längsten passen %.3f mm</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>process.lead_out.overlap_mm = %.6g mm: the profile cutter writes the torch height (Z) with it, and the chart &apos;%s&apos; gives no %s; set %s</source>
        <translation>process.lead_out.overlap_mm = %.6g mm: der Profilschneider schreibt damit die Brennerhöhe (Z), und die Tabelle &apos;%s&apos; gibt kein %s an; %s setzen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the %s needs X = %.3f mm, outside the carriage travel 0 .. machine.profile_cutter.x_travel_mm = %.3f mm</source>
        <translation>%s braucht X = %.3f mm, außerhalb des Schlittenwegs 0 .. machine.profile_cutter.x_travel_mm = %.3f mm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>too short: %zu samples for a %.3g s window</source>
        <translation>zu kurz: %zu Abtastwerte für ein Fenster von %.3g s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no period between %.4g s and %.4g s</source>
        <translation>keine Periode zwischen %.4g s und %.4g s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not periodic: the autocorrelation&apos;s best peak, at %.4g Hz, is %.2f (less than %.2f)</source>
        <translation>nicht periodisch: die höchste Spitze der Autokorrelation, bei %.4g Hz, beträgt %.2f (weniger als %.2f)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%.4g Hz oscillation below the floor (amplitude %.3g &lt;= %.3g)</source>
        <translation>Schwingung mit %.4g Hz unter der Schwelle (Amplitude %.3g &lt;= %.3g)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>decaying: the %.4g Hz oscillation falls to %.2f of its amplitude over the window (less than %.2f)</source>
        <translation>abklingend: die Schwingung mit %.4g Hz fällt im Fenster auf %.2f ihrer Amplitude (weniger als %.2f)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>limit cycle: %.4g Hz sustained (periodicity %.2f, late/early amplitude %.2f)</source>
        <translation>Grenzzyklus: %.4g Hz anhaltend (Periodizität %.2f, Amplitude spät/früh %.2f)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the k2 sweep would compute about %.3g samples (%d runs of %.3g), over the bound of %.3g</source>
        <translation>der k2-Durchlauf würde etwa %.3g Abtastwerte berechnen (%d Läufe zu %.3g), über der Grenze von %.3g</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the offline simulation would compute about %.3g samples (%zu controllers x (%.1f s of tracking + %d strokes of about %.2f s) / control.sample_time_s = %.3g s), over the bound of %.3g samples: use a longer sample time or fewer strokes</source>
        <translation>die Offline-Simulation würde etwa %.3g Abtastwerte rechnen (%zu Regler x (%.1f s Folgeregelung + %d Hübe von etwa %.2f s) / control.sample_time_s = %.3g s), über der Grenze von %.3g Abtastwerten: eine längere Abtastzeit oder weniger Hübe wählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>slider scale</source>
        <translation>Schieber-Positionssensor</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>tracking.amplitude_m = %.6g m about tracking.offset_m = %.6g m: the reference spans [%.6g, %.6g] m; it must stay inside the stroke (%.4f, %.4f) m</source>
        <translation>tracking.amplitude_m = %.6g m um tracking.offset_m = %.6g m: die Führungsgröße überstreicht [%.6g, %.6g] m; sie muss innerhalb des Hubs (%.4f, %.4f) m bleiben</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>pass %s (%s, s = %.1f mm, turning at the corner)</source>
        <translation>Durchgang %s (%s, s = %.1f mm, an der Ecke drehend)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pass %s (%s, s = %.1f mm)</source>
        <translation>Durchgang %s (%s, s = %.1f mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at %s: %s</source>
        <translation>bei %s: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the kerf %.6g mm is too wide for the %s bevel of %s (%s.angle_deg = %.6g deg) at %s: the bevel takes a strip %.6g mm wide off the face (along the bar), and the torch centre, k/2 across the bevel surface, would run %.6g mm into it - beyond the bar&apos;s end; the kerf may be at most %.6g mm here (k &lt;= 2 x strip x cos of the bevel surface to the bar)</source>
        <translation>die Schnittfuge %.6g mm ist zu breit für die %s-Fase von %s (%s.angle_deg = %.6g deg) bei %s: die Fase nimmt einen Streifen von %.6g mm von der Fläche (längs des Stabs), und die Brennermitte, k/2 quer zur Fasenfläche, liefe %.6g mm hinein - über das Stabende hinaus; die Schnittfuge darf hier höchstens %.6g mm sein (k &lt;= 2 x Streifen x cos der Fasenfläche zum Stab)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>process.override.cut_speed_mm_min = %.6g mm/min is not used by the section-steel cutter: it cuts at motion.speed_mm_s = %.6g mm/s (its process section gives the kerf); set the speed there</source>
        <translation>process.override.cut_speed_mm_min = %.6g mm/min wird von der Profilstahl-Schneidanlage nicht verwendet: sie schneidet mit motion.speed_mm_s = %.6g mm/s (ihr Prozessabschnitt gibt die Schnittfuge); die Geschwindigkeit dort einstellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>process.override.%s = %.6g %s is not used by the section-steel cutter (its process section gives the kerf only); remove it</source>
        <translation>process.override.%s = %.6g %s wird von der Profilstahl-Schneidanlage nicht verwendet (ihr Prozessabschnitt gibt nur die Schnittfuge); entfernen</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%s has %zu bytes: at most %d</source>
        <translation>%s hat %zu Bytes: höchstens %d</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>piece.quantity = %d pieces is outside [1, %d] pieces</source>
        <translation>piece.quantity = %d Stück liegt außerhalb von [1, %d] Stück</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the kerf %.6g mm is not a finite number</source>
        <translation>die Schnittfuge %.6g mm ist keine endliche Zahl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the kerf %.6g mm is negative: it must be 0 mm or more</source>
        <translation>die Schnittfuge %.6g mm ist negativ: sie muss 0 mm oder mehr sein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the kerf %.6g mm is too wide for a pipe of radius %.6g mm: at most %.6g mm (0.2 x the radius)</source>
        <translation>die Schnittfuge %.6g mm ist zu breit für ein Rohr mit Radius %.6g mm: höchstens %.6g mm (0,2 x Radius)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the torch axis is %.6g deg from the edge&apos;s tangent: at least %.6g deg is needed for a cut surface</source>
        <translation>die Brennerachse liegt %.6g° von der Tangente der Kante: für eine Schnittfläche sind mindestens %.6g° nötig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the cut surface is %.6g deg from the pipe surface: at least %.6g deg is needed to tell its sides</source>
        <translation>die Schnittfläche liegt %.6g° von der Rohroberfläche: mindestens %.6g° sind nötig, um ihre Seiten zu unterscheiden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the torch line %.6g mm off the edge misses the pipe surface of radius %.6g mm</source>
        <translation>die Brennerlinie %.6g mm neben der Kante verfehlt die Rohroberfläche mit Radius %.6g mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the cut surface is %.6g deg from the direction of the scrap side: at least %.6g deg is needed to tell its sides</source>
        <translation>die Schnittfläche liegt %.6g deg von der Richtung der Restseite: mindestens %.6g deg sind nötig, um ihre Seiten zu unterscheiden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the cut surface&apos;s normal is %.6g deg from the surface&apos;s lines (the bar axis): at most %.6g deg, else the torch runs more than %.3g x k/2 along them</source>
        <translation>die Normale der Schnittfläche liegt %.6g deg von den Mantellinien (der Stabachse): höchstens %.6g deg, sonst läuft der Brenner mehr als %.3g x k/2 entlang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at %.6g mm along the cut: %s</source>
        <translation>bei %.6g mm entlang des Schnitts: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the kerf %.6g mm is too wide for the edge at %.6g mm along the cut: its radius of curvature toward the scrap side is %.6g mm, the kerf may be at most %.6g mm</source>
        <translation>die Schnittfuge %.6g mm ist zu breit für die Kante bei %.6g mm entlang des Schnitts: ihr Krümmungsradius zur Abfallseite ist %.6g mm, die Schnittfuge darf höchstens %.6g mm sein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radius_mm = %.6g mm is not valid: the pipe radius must be more than 0 mm</source>
        <translation>radius_mm = %.6g mm ist ungültig: der Rohrradius muss größer als 0 mm sein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ovality_mm = %.6g mm is outside 0 .. %.6g mm (10 %% of the diameter %.6g mm)</source>
        <translation>ovality_mm = %.6g mm liegt außerhalb 0 .. %.6g mm (10 %% des Durchmessers %.6g mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>runout_mm = %.6g mm is outside 0 .. %.6g mm (a tenth of the radius %.6g mm)</source>
        <translation>runout_mm = %.6g mm liegt außerhalb 0 .. %.6g mm (ein Zehntel des Radius %.6g mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>taper_mm_per_m = %.6g mm/m is outside -%.6g .. %.6g mm/m</source>
        <translation>taper_mm_per_m = %.6g mm/m liegt außerhalb -%.6g .. %.6g mm/m</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>major_axis_deg = %.6g deg is not a finite number</source>
        <translation>major_axis_deg = %.6g deg ist keine endliche Zahl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>runout_deg = %.6g deg is not a finite number</source>
        <translation>runout_deg = %.6g deg ist keine endliche Zahl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>process.override.%s = %.6g %s is outside its range: above %.6g %s and at most %.6g %s</source>
        <oldsource>process.override.%s = %.6g %s is outside (%.6g, %.6g] %s: above %.6g %s and at most %.6g %s</oldsource>
        <translation>process.override.%s = %.6g %s liegt außerhalb des Bereichs: über %.6g %s und höchstens %.6g %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>process.override.%s = %.6g %s is outside [%.6g, %.6g] %s</source>
        <translation>process.override.%s = %.6g %s liegt außerhalb [%.6g, %.6g] %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>process.%s.kind = &quot;%s&quot; needs the %s height: the chart &apos;%s&apos; gives no %s; set %s (%s, [%.6g, %.6g] %s)</source>
        <translation>process.%s.kind = &quot;%s&quot; braucht die Höhe %s: die Schneidtabelle &apos;%s&apos; gibt kein %s; %s setzen (%s, [%.6g, %.6g] %s)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%s = %.6g %s is outside (%.6g, %.6g] %s</source>
        <translation>%s = %.6g %s liegt außerhalb (%.6g, %.6g] %s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Simulated cell: 6 drives + torch + arc voltage (out-of-round pipe)</source>
        <translation>Simulierte Zelle: 6 Antriebe + Brenner + Lichtbogenspannung (unrundes Rohr)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cycle %.3f ms needs %d frames (%d RPDO x %d bit + %d TPDO x %d bit + SYNC %d bit) + heartbeats %.1f bit = %.1f bit = %.1f %% of %.0f kbit/s; the limit is %.0f %%</source>
        <translation>Zyklus %.3f ms braucht %d Telegramme (%d RPDO x %d bit + %d TPDO x %d bit + SYNC %d bit) + Heartbeats %.1f bit = %.1f bit = %.1f %% von %.0f kbit/s; die Grenze ist %.0f %%</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s; use a period &gt;= %.1f ms</source>
        <translation>%s; eine Zykluszeit &gt;= %.1f ms wählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bus off</source>
        <translation>Bus aus (Bus-Off)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>transmitter error passive</source>
        <translation>Sender fehlerpassiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>receiver error passive</source>
        <translation>Empfänger fehlerpassiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error counter reached warning level</source>
        <translation>Fehlerzähler hat die Warnschwelle erreicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>back to error active</source>
        <translation>wieder fehleraktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>controller buffer overflow</source>
        <translation>Pufferüberlauf im Controller</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>controller restarted</source>
        <translation>Controller neu gestartet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>transmit timeout</source>
        <translation>Sendezeitüberschreitung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no acknowledge (no other node on the bus?)</source>
        <translation>keine Quittung (kein anderer Knoten am Bus?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>protocol violation</source>
        <translation>Protokollverletzung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bus error</source>
        <translation>Busfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error active</source>
        <translation>fehleraktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error warning</source>
        <translation>Fehlerwarnung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error passive</source>
        <translation>fehlerpassiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN plugin &quot;%s&quot; is not installed; installed: %s</source>
        <translation>CAN-Plugin „%s“ ist nicht installiert; installiert: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN interface &quot;%s&quot; is not offered by plugin %s; it offers: %s</source>
        <translation>CAN-Schnittstelle „%s“ wird vom Plugin %s nicht angeboten; es bietet: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN interface &quot;%s&quot; is not offered by plugin %s; it offers: %s (%s)</source>
        <translation>CAN-Schnittstelle „%s“ wird vom Plugin %s nicht angeboten; es bietet: %s (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot create eventfd for the CAN master</source>
        <translation>eventfd für den CAN-Master kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN connection to %s %s did not come up within %d ms</source>
        <translation>CAN-Verbindung zu %s %s kam nicht innerhalb von %d ms zustande</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no CAN nodes configured</source>
        <translation>keine CAN-Knoten konfiguriert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bus load too high: %s</source>
        <translation>CAN-Buslast zu hoch: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recovering the bus: reconnecting and configuring the nodes again</source>
        <translation>Bus wird wiederhergestellt: neu verbinden und die Knoten neu konfigurieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node %d: %s</source>
        <translation>Knoten %d: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bus: %s</source>
        <translation>CAN-Bus: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not ready to switch on</source>
        <translation>Nicht einschaltbereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switch on disabled</source>
        <translation>Einschaltsperre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ready to switch on</source>
        <translation>Einschaltbereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switched on</source>
        <translation>Eingeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Operation enabled</source>
        <translation>Betrieb freigegeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quick stop active</source>
        <translation>Schnellhalt aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fault reaction active</source>
        <translation>Fehlerreaktion aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unknown</source>
        <translation>Unbekannt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0x%04X device specific</source>
        <translation>0x%04X gerätespezifisch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0x%04X %s</source>
        <translation>0x%04X %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0x%04X %s (class)</source>
        <translation>0x%04X %s (Klasse)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0x%04X unknown error code</source>
        <translation>0x%04X unbekannter Fehlercode</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error reset or no error</source>
        <translation>Fehler zurückgesetzt oder kein Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>continuous over-current</source>
        <translation>andauernder Überstrom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>short circuit or earth leakage</source>
        <translation>Kurzschluss oder Erdschluss</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DC link over-voltage</source>
        <translation>Zwischenkreis-Überspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DC link under-voltage</source>
        <translation>Zwischenkreis-Unterspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>excess temperature, device</source>
        <translation>Übertemperatur, Gerät</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>excess temperature, drive</source>
        <translation>Übertemperatur, Antrieb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data storage (non-volatile memory)</source>
        <translation>Datenspeicher (nichtflüchtiger Speicher)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>motor blocked</source>
        <translation>Motor blockiert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>incremental sensor 1 fault</source>
        <translation>Fehler Inkrementalgeber 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN overrun (objects lost)</source>
        <translation>CAN-Überlauf (Objekte verloren)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN in error passive mode</source>
        <translation>CAN im fehlerpassiven Zustand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>life guard or heartbeat error</source>
        <translation>Life-Guarding- oder Heartbeat-Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recovered from bus off</source>
        <translation>vom Bus-Off erholt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN-ID collision</source>
        <translation>CAN-ID-Kollision</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO not processed due to length error</source>
        <translation>PDO wegen Längenfehler nicht verarbeitet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO length exceeded</source>
        <translation>PDO-Länge überschritten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexpected SYNC data length</source>
        <translation>unerwartete SYNC-Datenlänge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RPDO timeout</source>
        <translation>RPDO-Zeitüberschreitung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>following error</source>
        <translation>Schleppfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reference limit</source>
        <translation>Referenzgrenze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>current, device input side</source>
        <translation>Strom, Geräteeingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>current inside the device</source>
        <translation>Strom im Gerät</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>current, device output side</source>
        <translation>Strom, Geräteausgang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mains voltage</source>
        <translation>Netzspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>voltage inside the device</source>
        <translation>Spannung im Gerät</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>output voltage</source>
        <translation>Ausgangsspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ambient temperature</source>
        <translation>Umgebungstemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device temperature</source>
        <translation>Gerätetemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drive temperature</source>
        <translation>Antriebstemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>internal software</source>
        <translation>interne Software</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>user software</source>
        <translation>Anwendersoftware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data set</source>
        <translation>Datensatz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>power (motor)</source>
        <translation>Leistung (Motor)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sensor</source>
        <translation>Sensor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>communication</source>
        <translation>Kommunikation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>protocol error</source>
        <translation>Protokollfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torque control</source>
        <translation>Momentenregelung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>velocity speed controller</source>
        <translation>Drehzahlregler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position controller</source>
        <translation>Lageregler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>positioning controller</source>
        <translation>Positionierregler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>generic error</source>
        <translation>allgemeiner Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device hardware</source>
        <translation>Gerätehardware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device software</source>
        <translation>Gerätesoftware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>additional modules</source>
        <translation>Zusatzmodule</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>monitoring</source>
        <translation>Überwachung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>external error</source>
        <translation>externer Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>additional functions</source>
        <translation>Zusatzfunktionen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot create CAN device %s %s: %s</source>
        <translation>CAN-Gerät %s %s kann nicht angelegt werden: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN device %s %s: %s</source>
        <translation>CAN-Gerät %s %s: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device error: %s</source>
        <translation>Gerätefehler: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>connection to the bus lost</source>
        <translation>Verbindung zum Bus verloren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s: every drive is in Fault; recover the bus, then reset the faults</source>
        <translation>%s: alle Antriebe sind im Fehler; den Bus wiederherstellen, dann die Fehler quittieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMT %s to node %d</source>
        <translation>NMT %s an Knoten %d</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMT %s to all nodes</source>
        <translation>NMT %s an alle Knoten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a SYNC (0x080)</source>
        <translation>ein SYNC (0x080)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s (0x000)</source>
        <translation>%s (0x000)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a heartbeat of the master&apos;s node %d (0x%03X)</source>
        <translation>ein Heartbeat des Master-Knotens %d (0x%03X)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>another CANopen master is on the bus (heard %s, not sent by this master): every drive disabled and pre-operational, this master gave up the bus</source>
        <translation>ein anderer CANopen-Master ist auf dem Bus (%s gehört, nicht von diesem Master gesendet): jeder Antrieb abgeschaltet und in „Pre-Operational“, dieser Master hat den Bus aufgegeben</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%s refused: %s (a node without a SYNC counter: set devices.sync_counter_overflow = 0)</source>
        <translation>%s abgelehnt: %s (ein Knoten ohne SYNC-Zähler: devices.sync_counter_overflow = 0 setzen)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>no position value (TPDO) for %lld ms after a SYNC (&gt; %lld ms): the encoder&apos;s reading is lost; last heartbeat %lld ms ago</source>
        <translation>kein Positionswert (TPDO) seit %lld ms nach einem SYNC (&gt; %lld ms): der Messwert des Gebers ist verloren; letzter Heartbeat vor %lld ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no process data (TPDO) for %lld ms after a SYNC (&gt; %lld ms): the drive&apos;s feedback is lost; last heartbeat %lld ms ago</source>
        <translation>keine Prozessdaten (TPDO) seit %lld ms nach einem SYNC (&gt; %lld ms): die Rückmeldung des Antriebs ist verloren; letzter Heartbeat vor %lld ms</translation>
    </message>
    <message>
        <location line="-27"/>
        <source>%d SYNC (0x080)</source>
        <translation>%d SYNC (0x080)</translation>
    </message>
    <message>
        <location line="-248"/>
        <source>point %zu of the %s (x/y/z = %.2f/%.2f/%.2f mm): %s</source>
        <translation>Punkt %zu von %s (x/y/z = %.2f/%.2f/%.2f mm): %s</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>pierce height %.6g mm is below the cut height %.6g mm: the torch pierces above the cut height, then comes down to it; set process.override.pierce_height_mm to at least %.6g mm</source>
        <translation>die Einstechhöhe %.6g mm liegt unter der Schneidhöhe %.6g mm: der Brenner sticht über der Schneidhöhe ein und senkt sich dann auf sie ab; process.override.pierce_height_mm auf mindestens %.6g mm setzen</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>process.lead_out.overlap_mm = %.6g mm: the section-steel cutter&apos;s cut is open (it starts and ends at the free edges beside the face on the conveyor): there is no start to overlap; remove it</source>
        <translation>process.lead_out.overlap_mm = %.6g mm: der Schnitt der Profilstahl-Schneidanlage ist offen (er beginnt und endet an den freien Kanten neben der Fläche auf dem Förderer): es gibt keinen Anfang zum Überlappen; entfernen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>process.%s.kind = &quot;%s&quot;: setup 2 (end_cut.setup = 2) cuts only bevels, which start and end off the material and take no lead; set &quot;none&quot; or remove it</source>
        <translation>process.%s.kind = &quot;%s&quot;: Aufspannung 2 (end_cut.setup = 2) schneidet nur Fasen, die außerhalb des Materials beginnen und enden und keinen An- oder Ausschnitt nehmen; &quot;none&quot; setzen oder entfernen</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>point %zu of pass %s (the %s at %s): %s</source>
        <translation>Punkt %zu von Durchgang %s (%s bei %s): %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pierce</source>
        <translation>Einstich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lead-in</source>
        <translation>Anschnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lead-out</source>
        <translation>Ausschnitt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the point x = %.1f, y = %.1f, z = %.1f mm is off the path arm&apos;s plane (a planar 3R arm in the cut plane)</source>
        <translation>der Punkt x = %.1f, y = %.1f, z = %.1f mm liegt außerhalb der Ebene des Bahnarms (ein ebener 3R-Arm in der Schnittebene)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the torch body hits the section %.0f mm behind the tip at x = %.1f, y = %.1f, z = %.1f mm (torch_length_mm = %.0f, torch_radius_mm = %.0f)</source>
        <translation>der Brennerkörper trifft das Profil %.0f mm hinter der Spitze bei x = %.1f, y = %.1f, z = %.1f mm (torch_length_mm = %.0f, torch_radius_mm = %.0f)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at x = %.1f, y = %.1f, z = %.1f mm: %s</source>
        <translation>bei x = %.1f, y = %.1f, z = %.1f mm: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>process.%s.length_mm = %.6g mm is too long for the section-steel cutter: the %s (%s, off the free edge in the path arm&apos;s plane) cannot be cut %s; the longest that fits is %.3f mm</source>
        <translation>process.%s.length_mm = %.6g mm ist zu lang für die Profilstahl-Schneidanlage: %s (%s, außerhalb der freien Kante in der Ebene des Bahnarms) kann nicht geschnitten werden %s; am längsten passen %.3f mm</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>process.torch_height: the %s has no torch height control (the pipe robot has); remove it</source>
        <translation>process.torch_height: %s hat keine Brennerhöhenregelung (der Rohrroboter hat eine); entfernen</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>%d NMT commands (0x000, %s)</source>
        <translation>%d NMT-Befehle (0x000, %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%d NMT command (0x000, %s)</source>
        <translation>%d NMT-Befehl (0x000, %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%d master heartbeats of node %d (0x%03X)</source>
        <translation>%d Master-Heartbeats von Knoten %d (0x%03X)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%d master heartbeat of node %d (0x%03X)</source>
        <translation>%d Master-Heartbeat von Knoten %d (0x%03X)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>another CANopen master is active on %s %s: heard %s within %d ms; not taking the bus</source>
        <translation>ein anderer CANopen-Master ist auf %s %s aktiv: %s gehört innerhalb von %d ms; der Bus wird nicht übernommen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>connected, no other master heard in %d ms; %s</source>
        <translation>verbunden, kein anderer Master in %d ms gehört; %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO read %s:%s</source>
        <translation>SDO-Lesen %s:%s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO write %s:%s = %s</source>
        <translation>SDO-Schreiben %s:%s = %s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%s: unexpected SDO answer (segmented transfer?)</source>
        <translation>%s: unerwartete SDO-Antwort (segmentierte Übertragung?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device type %s is not a CiA 406 encoder (profile %u)</source>
        <translation>Gerätetyp %s ist kein CiA-406-Geber (Profil %u)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device type %s is not a CiA 402 drive (profile %u)</source>
        <translation>Gerätetyp %s ist kein CiA-402-Antrieb (Profil %u)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>motor rated torque 0x6076 = 0: no scale for the target torque (CST)</source>
        <translation>Motornennmoment 0x6076 = 0: kein Maßstab für das Sollmoment (CST)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bus off (%s)</source>
        <translation>Bus aus (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a %s to node %d (0x%03X)</source>
        <translation>ein %s an Knoten %d (0x%03X)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node rebooted while running (unexpected boot-up)</source>
        <translation>Knoten im Betrieb neu gestartet (unerwartetes Boot-up)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>configured (CiA 406 encoder, TPDO1 position value, heartbeat %d ms) and operational</source>
        <translation>konfiguriert (CiA-406-Geber, TPDO1 Positionswert, Heartbeat %d ms) und betriebsbereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>configured (CST, RPDO1/RPDO2/TPDO1, heartbeat %d ms) and operational</source>
        <translation>konfiguriert (CST, RPDO1/RPDO2/TPDO1, Heartbeat %d ms) und betriebsbereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>configured (CSP, RPDO1/RPDO2/TPDO1, heartbeat %d ms) and operational</source>
        <translation>konfiguriert (CSP, RPDO1/RPDO2/TPDO1, Heartbeat %d ms) und betriebsbereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EMCY %s (error register %s)</source>
        <translation>EMCY %s (Fehlerregister %s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fault reset: configuring the node again</source>
        <translation>Fehler quittiert: der Knoten wird neu konfiguriert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no boot-up within %d ms after NMT reset communication (is a node with this id on the bus?)</source>
        <translation>kein Boot-up innerhalb von %d ms nach NMT Reset Communication (ist ein Knoten mit dieser ID am Bus?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO %s:%s unanswered after %d tries of %d ms: %s</source>
        <translation>SDO %s:%s nach %d Versuchen zu je %d ms unbeantwortet: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no Operational heartbeat after NMT start</source>
        <translation>kein Heartbeat „Operational“ nach NMT-Start</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heartbeat lost (none for %lld ms &gt; %lld ms)</source>
        <translation>Heartbeat verloren (keiner seit %lld ms &gt; %lld ms)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bus state: %s</source>
        <translation>Buszustand: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>start</source>
        <translation>Start</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>enter pre-operational</source>
        <translation>Pre-Operational einleiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reset node</source>
        <translation>Knoten zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reset communication</source>
        <translation>Kommunikation zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Boot-up</source>
        <translation>Boot-up</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Operational</source>
        <translation>Operational</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pre-operational</source>
        <translation>Pre-Operational</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0x%08X: %s</source>
        <translation>0x%08X: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0x%08X: unknown abort code</source>
        <translation>0x%08X: unbekannter Abbruchcode</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>toggle bit not alternated</source>
        <translation>Toggle-Bit nicht gewechselt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO protocol timed out</source>
        <translation>Zeitüberschreitung im SDO-Protokoll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>client/server command specifier not valid or unknown</source>
        <translation>Client/Server-Befehlskennung ungültig oder unbekannt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid block size</source>
        <translation>ungültige Blockgröße</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid sequence number</source>
        <translation>ungültige Sequenznummer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CRC error</source>
        <translation>CRC-Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>out of memory</source>
        <translation>Speicher voll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unsupported access to an object</source>
        <translation>nicht unterstützter Zugriff auf ein Objekt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attempt to read a write-only object</source>
        <translation>Versuch, ein nur schreibbares Objekt zu lesen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attempt to write a read-only object</source>
        <translation>Versuch, ein nur lesbares Objekt zu schreiben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>object does not exist in the object dictionary</source>
        <translation>Objekt existiert nicht im Objektverzeichnis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>object cannot be mapped to the PDO</source>
        <translation>Objekt kann nicht auf das PDO abgebildet werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the number and length of the objects to be mapped would exceed the PDO length</source>
        <translation>Anzahl und Länge der abzubildenden Objekte würden die PDO-Länge überschreiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>general parameter incompatibility</source>
        <translation>allgemeine Parameterunverträglichkeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>general internal incompatibility in the device</source>
        <translation>allgemeine interne Unverträglichkeit im Gerät</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>access failed due to a hardware error</source>
        <translation>Zugriff wegen eines Hardwarefehlers gescheitert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data type does not match, length of service parameter does not match</source>
        <translation>Datentyp passt nicht, Länge des Dienstparameters passt nicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data type does not match, length of service parameter too high</source>
        <translation>Datentyp passt nicht, Länge des Dienstparameters zu groß</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data type does not match, length of service parameter too low</source>
        <translation>Datentyp passt nicht, Länge des Dienstparameters zu klein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sub-index does not exist</source>
        <translation>Subindex existiert nicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid value for parameter</source>
        <translation>ungültiger Wert für den Parameter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>value of parameter written too high</source>
        <translation>geschriebener Parameterwert zu groß</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>value of parameter written too low</source>
        <translation>geschriebener Parameterwert zu klein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>maximum value is less than minimum value</source>
        <translation>Maximalwert ist kleiner als der Minimalwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>resource not available: SDO connection</source>
        <translation>Ressource nicht verfügbar: SDO-Verbindung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>general error</source>
        <translation>allgemeiner Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data cannot be transferred or stored to the application</source>
        <translation>Daten können nicht an die Anwendung übertragen oder dort gespeichert werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data cannot be transferred or stored to the application because of local control</source>
        <translation>Daten können wegen lokaler Steuerung nicht an die Anwendung übertragen oder dort gespeichert werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data cannot be transferred or stored to the application because of the present device state</source>
        <translation>Daten können wegen des aktuellen Gerätezustands nicht an die Anwendung übertragen oder dort gespeichert werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>object dictionary dynamic generation failed or no object dictionary is present</source>
        <translation>dynamische Erzeugung des Objektverzeichnisses gescheitert oder kein Objektverzeichnis vorhanden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no data available</source>
        <translation>keine Daten verfügbar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nodes %s: %s</source>
        <translation>Knoten %s: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node %s: %s</source>
        <translation>Knoten %s: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not connected (%s)</source>
        <translation>nicht verbunden (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>disconnected from %s</source>
        <translation>getrennt von %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>connecting to %s (listening for another master)</source>
        <translation>verbinde mit %s (horche auf einen anderen Master)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bus %s: %s</source>
        <translation>CAN-Bus %s: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>connected to %s; configuring the nodes</source>
        <translation>verbunden mit %s; die Knoten werden konfiguriert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bus went away while configuring (%s)</source>
        <translation>der Bus ging während der Konfiguration verloren (%s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>every node operational on %s; reading the drives&apos; states</source>
        <translation>alle Knoten auf %s betriebsbereit; die Zustände der Antriebe werden gelesen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up on %s: %d nodes operational</source>
        <translation>bereit auf %s: %d Knoten betriebsbereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%d of %d nodes did not come up: %s</source>
        <translation>%d von %d Knoten sind nicht hochgefahren: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%d of %d nodes did not come up (within %d ms): %s</source>
        <translation>%d von %d Knoten sind nicht hochgefahren (innerhalb von %d ms): %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>configuring the nodes on %s: %d of %d operational</source>
        <translation>Knoten auf %s werden konfiguriert: %d von %d betriebsbereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bus lost on %s: %s</source>
        <translation>CAN-Bus auf %s verloren: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up on %s; %d node(s) not operational: %s</source>
        <translation>bereit auf %s; %d Knoten nicht betriebsbereit: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%d CiA 402 drives (CSP)</source>
        <translation>%d CiA-402-Antriebe (CSP)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%d CiA 402 drives (CST)</source>
        <translation>%d CiA-402-Antriebe (CST)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%d CiA 402 drives (%d CSP, %d CST)</source>
        <translation>%d CiA-402-Antriebe (%d CSP, %d CST)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s + CiA 406 encoder %d (%s)</source>
        <translation>%s + CiA-406-Geber %d (%s)</translation>
    </message>
    <message>
        <location line="-318"/>
        <source>path not reachable (%s method): %s</source>
        <translation>Bahn nicht erreichbar (Verfahren %s): %s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the cut needs X = %.3f mm (beta = %.2f deg), outside the carriage travel 0 .. machine.profile_cutter.x_travel_mm = %.3f mm</source>
        <translation>der Schnitt braucht X = %.3f mm (beta = %.2f deg), außerhalb des Wagenwegs 0 .. machine.profile_cutter.x_travel_mm = %.3f mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>other_branches[%zu].angle_deg = %.6g deg is outside [0.1, 179.9] deg (angle to the main axis)</source>
        <translation>other_branches[%zu].angle_deg = %.6g deg liegt außerhalb von [0,1, 179,9] deg (Winkel zur Hauptachse)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>other_branches[%zu].radius_mm = %.6g mm does not fit: |eccentricity_mm| + radius = %.6g mm must be &lt;= main_pipe.radius_mm = %.6g mm</source>
        <translation>other_branches[%zu].radius_mm = %.6g mm passt nicht: |eccentricity_mm| + Radius = %.6g mm muss &lt;= main_pipe.radius_mm = %.6g mm sein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>other_branches[%zu]: its axis is %.6g deg from the cut branch&apos;s axis; it must differ by &gt;= 1 deg</source>
        <translation>other_branches[%zu]: seine Achse liegt %.6g deg von der Achse des geschnittenen Abzweigs; sie muss um &gt;= 1 deg abweichen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut.bevel_deg = %.6g deg: the 2-axis profile cutter cuts square only (0 deg)</source>
        <translation>cut.bevel_deg = %.6g deg: der 2-Achsen-Profilschneider schneidet nur rechtwinklig (0 deg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the profile cutter&apos;s A and X steppers are driven by a pulse card, not by CANopen drives: use devices.kind = &quot;simulated&quot;</source>
        <translation>die Schrittmotoren A und X des Profilschneiders werden von einer Pulskarte angesteuert, nicht von CANopen-Antrieben: devices.kind = &quot;simulated&quot; verwenden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not feasible: %s</source>
        <translation>nicht ausführbar: %s</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>step %zu (beta = %.3f deg) needs %.0f Hz on the %s axis, above machine.profile_cutter.max_pulse_rate_hz = %.0f Hz: lower cut.speed_mm_s</source>
        <translation>Schritt %zu (beta = %.3f deg) braucht %.0f Hz auf der Achse %s, mehr als machine.profile_cutter.max_pulse_rate_hz = %.0f Hz: cut.speed_mm_s senken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>did not finish %d strokes in %d s</source>
        <translation>%d Hübe nicht in %d s beendet</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>holding</source>
        <translation>hält</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>open-loop return (push)</source>
        <translation>gesteuerter Rückhub (Schub)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>open-loop return (brake)</source>
        <translation>gesteuerter Rückhub (Bremsen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>near a singular point: no crank reference (parabolic blend)</source>
        <translation>nahe einem singulären Punkt: keine Kurbelführung (Parabelübergang)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>braking the crank</source>
        <translation>Bremsen der Kurbel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cutting stroke: the crank was driven back through the top singular point (the controller cannot hold the slider against the contact force)</source>
        <translation>Schnitthub: die Kurbel wurde durch den oberen singulären Punkt zurückgedrückt (der Regler kann den Schieber gegen die Kontaktkraft nicht halten)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cutting stroke stalled: the slider did not reach the end of the stroke in time (the controller cannot push through the contact force)</source>
        <translation>Schnitthub blockiert: der Schieber erreichte das Hubende nicht rechtzeitig (der Regler kann die Kontaktkraft nicht überwinden)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>open-loop return stalled before the top of the stroke: raise return_torque_1 or lower |return_torque_2|</source>
        <translation>gesteuerter Rückhub vor dem oberen Hubende blockiert: return_torque_1 erhöhen oder |return_torque_2| senken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cutter</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cutter ready</source>
        <translation>Werkzeug bereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cutter lost</source>
        <translation>Werkzeug verloren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>control.osmc: Q = [q11 q12; q12 q22] = [%.6g %.6g; %.6g %.6g] must be positive definite</source>
        <translation>control.osmc: Q = [q11 q12; q12 q22] = [%.6g %.6g; %.6g %.6g] muss positiv definit sein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mechanism: the loop (B.1) does not close for crank angles q in %s: |Dx - O3x - (r3 + AB) cos(theta3)| &gt; r4 = %.6g m there, so the crank cannot turn fully</source>
        <translation>mechanism: die Schleife (B.1) schließt sich nicht für Kurbelwinkel q in %s: dort ist |Dx - O3x - (r3 + AB) cos(theta3)| &gt; r4 = %.6g m, die Kurbel kann sich nicht ganz drehen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mechanism.r4_m = %.6g m: the link comes within %.4f of horizontal (1 - |cos theta4|), a singular pose; the limit is 0.02</source>
        <translation>mechanism.r4_m = %.6g m: das Glied kommt der Waagerechten bis auf %.4f nahe (1 - |cos theta4|), eine singuläre Stellung; die Grenze ist 0,02</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mechanism: no two singular crank angles (rho_y = 0) were found</source>
        <translation>mechanism: keine zwei singulären Kurbelwinkel (rho_y = 0) gefunden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut.stroke_length_m = %.6g m does not match the mechanism&apos;s stroke y_min - y_max = %.4f m (tolerance 0.002 m)</source>
        <translation>cut.stroke_length_m = %.6g m passt nicht zum Hub des Mechanismus y_min - y_max = %.4f m (Toleranz 0,002 m)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut.workpiece_length_m = %.6g m must be in (0, %.4f) m (the stroke L_c)</source>
        <translation>cut.workpiece_length_m = %.6g m muss in (0, %.4f) m liegen (der Hub L_c)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut.velocity_m_s = %.6g m/s is outside [-10, 0) m/s (the cut runs downwards)</source>
        <translation>cut.velocity_m_s = %.6g m/s liegt außerhalb von [-10, 0) m/s (der Schnitt läuft abwärts)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the mechanism has no full crank turn with two singular points</source>
        <translation>der Mechanismus hat keine volle Kurbeldrehung mit zwei singulären Punkten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Algorithm 1: %s</source>
        <translation>Algorithmus 1: %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the cutting velocity must be a finite number other than 0</source>
        <translation>die Schnittgeschwindigkeit muss eine endliche Zahl ungleich 0 sein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the workpiece length L_d must be &gt; 0 and shorter than the stroke L_c</source>
        <translation>die Werkstücklänge L_d muss &gt; 0 und kürzer als der Hub L_c sein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the cutting velocity&apos;s sign must point from the stroke start to its end</source>
        <translation>das Vorzeichen der Schnittgeschwindigkeit muss vom Hubanfang zum Hubende zeigen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>horizontal leg</source>
        <translation>waagerechten Schenkels</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bottom flange</source>
        <translation>unteren Flanschs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>end_cut.setup = 2 (the section turned over): nothing is left to cut - setup 2 cuts only the bevel on the underside of the %s (on the conveyor in setup 1) that a K groove on the flanges needs, and end_cut.flanges.groove = &quot;%s&quot;; plan setup 1 (end_cut.setup = 1)</source>
        <translation>end_cut.setup = 2 (Profil gewendet): nichts mehr zu schneiden - Aufspannung 2 schneidet nur die Fase an der Unterseite des %s (auf dem Förderer in Aufspannung 1), die eine K-Fuge an den Flanschen braucht, und end_cut.flanges.groove = &quot;%s&quot;; Aufspannung 1 planen (end_cut.setup = 1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%s.%s = %.6g mm is outside [%.6g, %.6g] mm</source>
        <translation>%s.%s = %.6g mm liegt außerhalb von [%.6g, %.6g] mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s.r2_mm = %.6g mm: the toe radius must be below the thickness (%.6g mm)</source>
        <translation>%s.r2_mm = %.6g mm: der Kantenradius muss unter der Dicke liegen (%.6g mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s.r_mm = %.6g mm leaves no flat flange: it must be below %.6g mm (flange outstand)</source>
        <translation>%s.r_mm = %.6g mm lässt keinen ebenen Flansch: er muss unter %.6g mm liegen (Flanschüberstand)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s.r_mm = %.6g mm: two root radii do not fit between the flanges (%.6g mm)</source>
        <translation>%s.r_mm = %.6g mm: zwei Ausrundungsradien passen nicht zwischen die Flansche (%.6g mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s.r_mm = %.6g mm does not fit on the vertical leg (%.6g mm)</source>
        <translation>%s.r_mm = %.6g mm passt nicht auf den senkrechten Schenkel (%.6g mm)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%s (and %zu more points)</source>
        <translation>%s (und %zu weitere Punkte)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%s joint %s = %.2f deg is outside its limits [%.1f, %.1f] deg</source>
        <translation>%s, Gelenk %s = %.2f deg liegt außerhalb seiner Grenzen [%.1f, %.1f] deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s: no inverse-kinematics solution (out of reach)</source>
        <translation>%s: keine Lösung der inversen Kinematik (außer Reichweite)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s (all %zu branches)</source>
        <translation>%s (alle %zu Lösungszweige)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>point %zu of pass %s (%s, turning at the corner, s = %.1f mm): %s</source>
        <translation>Punkt %zu des Durchgangs %s (%s, Drehung an der Ecke, s = %.1f mm): %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point %zu of pass %s (%s, s = %.1f mm): %s</source>
        <translation>Punkt %zu des Durchgangs %s (%s, s = %.1f mm): %s</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the torch body hits the section %.0f mm behind the tip at x = %.1f, y = %.1f, z = %.1f mm (torch_length_mm = %.0f, torch_radius_mm = %.0f, lean %.0f deg of max_lean_deg = %.0f)</source>
        <translation>der Brennerkörper trifft das Profil %.0f mm hinter der Spitze bei x = %.1f, y = %.1f, z = %.1f mm (torch_length_mm = %.0f, torch_radius_mm = %.0f, Neigung %.0f deg von max_lean_deg = %.0f)</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>path arm</source>
        <translation>Bahnarm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>path arm changes branch (joint jump %.1f deg)</source>
        <translation>Bahnarm wechselt den Lösungszweig (Gelenksprung %.1f deg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>groove arm</source>
        <translation>Fugenarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>groove arm changes branch (joint jump %.1f deg)</source>
        <translation>Fugenarm wechselt den Lösungszweig (Gelenksprung %.1f deg)</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>the cut has no path</source>
        <translation>der Schnitt hat keine Bahn</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%s.root_face_mm = %.6g mm: a V groove has no root face (use Y)</source>
        <translation>%s.root_face_mm = %.6g mm: eine V-Fuge hat keinen Steg (Y verwenden)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>end_cut.setup = %d is outside [1, %d]</source>
        <translation>end_cut.setup = %d liegt außerhalb von [1, %d]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s.min_deg = %.6g deg must be below max_deg = %.6g deg</source>
        <translation>%s.min_deg = %.6g deg muss unter max_deg = %.6g deg liegen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>park_deg[%zu] = %.6g deg is outside %s [%.6g, %.6g] deg</source>
        <translation>park_deg[%zu] = %.6g deg liegt außerhalb von %s [%.6g, %.6g] deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drives[%zu].tau_f_s = %.6g s must be &gt;= half the control period (%.6g s)</source>
        <translation>drives[%zu].tau_f_s = %.6g s muss &gt;= der halben Regelperiode sein (%.6g s)</translation>
    </message>
    <message>
        <location line="-111"/>
        <source>point %zu (phi = %.2f deg, s = %.2f mm, x/y/z = %.2f/%.2f/%.2f mm): %s</source>
        <translation>Punkt %zu (phi = %.2f deg, s = %.2f mm, x/y/z = %.2f/%.2f/%.2f mm): %s</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>planning cancelled</source>
        <translation>Planung abgebrochen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>joint 0 (chuck) = %.3f deg is past its range [%.1f, %.1f] deg</source>
        <translation>Gelenk 0 (Futter) = %.3f deg liegt außerhalb seines Bereichs [%.1f, %.1f] deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the torch must tilt %.2f deg into the plane of joint 1 (5-DOF arm), more than cut.max_direction_deviation_deg = %.2f deg</source>
        <translation>der Brenner müsste sich %.2f deg in die Ebene von Gelenk 1 neigen (5-achsiger Arm), mehr als cut.max_direction_deviation_deg = %.2f deg</translation>
    </message>
    <message>
        <location line="+131"/>
        <source>tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated flying saw: line encoder, carriage, turntable, 2 feeds + saw</source>
        <translation>Simulierte fliegende Säge: Liniengeber, Wagen, Drehtisch, 2 Blattvorschübe + Säge</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated cell: 6 drives + torch</source>
        <translation>Simulierte Zelle: 6 Antriebe + Brenner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated profile cutter: A and X steppers + torch</source>
        <translation>Simulierter Profilschneider: Schrittmotoren A und X + Brenner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated quick-return cutter: crank drive (CST) + slider scale</source>
        <translation>Simulierte Schnellrücklauf-Schneidmaschine: Kurbelantrieb (CST) + Schiebermaßstab</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated cell: 8 drives + torch</source>
        <translation>Simulierte Zelle: 8 Antriebe + Brenner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%s, %.3g ms cycle, %s</source>
        <translation>%s, Zyklus %.3g ms, %s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>real time</source>
        <translation>Echtzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>as fast as possible</source>
        <translation>so schnell wie möglich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CANopen cell: %s on %s at %d kbit/s + simulated tool, %.3g ms SYNC, real time</source>
        <translation>CANopen-Zelle: %s an %s mit %d kbit/s + simuliertes Werkzeug, SYNC %.3g ms, Echtzeit</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::AccessControl</name>
    <message>
        <location filename="../../ui/access_control.cpp" line="+20"/>
        <source>operator</source>
        <translation>Bediener</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>setter</source>
        <translation>Einrichter</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>engineer</source>
        <translation>Ingenieur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>administrator</source>
        <translation>Administrator</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>The user list cannot be read (%1): the fields stay locked</source>
        <translation>Die Benutzerliste kann nicht gelesen werden (%1): die Felder bleiben gesperrt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Log in to change this (needs the %1 level)</source>
        <translation>Zum Ändern anmelden (braucht die Stufe %1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Needs the %1 level (%2 is logged in as %3)</source>
        <translation>Braucht die Stufe %1 (%2 ist als %3 angemeldet)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is logged in as %2</source>
        <translation>%1 ist als %2 angemeldet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nobody is logged in</source>
        <translation>niemand ist angemeldet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it is a job for another machine (%1): opening it needs the %2 level (%3)</source>
        <translation>es ist ein Auftrag für eine andere Maschine (%1): Öffnen braucht die Stufe %2 (%3)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>it changes %1 from %2 to %3: opening it needs the %4 level (%5)</source>
        <translation>er ändert %1 von %2 auf %3: Öffnen braucht die Stufe %4 (%5)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the user list cannot be read (%1): repair it, or start with --record off to run without users</source>
        <translation>die Benutzerliste kann nicht gelesen werden (%1): reparieren oder mit --record off ohne Benutzer starten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>log in to run (E-STOP and feed hold work without log-in)</source>
        <translation>zum Fahren anmelden (NOT-HALT und Vorschub-Halt wirken ohne Anmeldung)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+12"/>
        <source>no user list here</source>
        <translation>hier gibt es keine Benutzerliste</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::AlarmPanel</name>
    <message>
        <location filename="../../ui/panels/alarm_panel.cpp" line="+46"/>
        <source>Acknowledge</source>
        <translation>Quittieren</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The operator has seen the alarms; they stay active until Reset [%1].</source>
        <translation>Der Bediener hat die Alarme zur Kenntnis genommen; sie bleiben aktiv bis Reset [%1].</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>What to do</source>
        <translation>Abhilfe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>engine</source>
        <translation>Steuerung</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Check the axis for a collision or binding, then its gains and the following error limit.</source>
        <translation>Achse auf Kollision oder Schwergängigkeit prüfen, dann ihre Reglerverstärkungen und die Schleppfehlergrenze.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Look the drive&apos;s fault code up in its manual (Devices tab); remove the cause.</source>
        <translation>Fehlercode des Antriebs im Handbuch nachschlagen (Registerkarte Geräte); Ursache beseitigen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Check the encoder, its cable and the bus.</source>
        <translation>Geber, Geberkabel und Bus prüfen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Check the drive&apos;s power and its enable chain.</source>
        <translation>Spannungsversorgung und Freigabekette des Antriebs prüfen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Check gas, consumables and the work clamp.</source>
        <translation>Gas, Verschleißteile und Masseklemme prüfen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Check the CAN cable, the node&apos;s power and the bus termination.</source>
        <translation>CAN-Kabel, Spannungsversorgung des Knotens und Busabschluss prüfen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Check the axes&apos; tuning and the in-position window.</source>
        <translation>Reglereinstellung der Achsen und Positionierfenster prüfen.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>operator (E-STOP)</source>
        <translation>Bediener (NOT-HALT)</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>No alarms.</source>
        <translation>Keine Alarme.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 active, %2 not acknowledged, %3 in the list</source>
        <translation>%1 aktiv, %2 nicht quittiert, %3 in der Liste</translation>
    </message>
    <message>
        <location line="+46"/>
        <location line="+18"/>
        <source>Cannot write the alarm list &apos;%1&apos;: %2</source>
        <translation>Alarmliste &apos;%1&apos; kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::BusPanel</name>
    <message>
        <location filename="../../ui/panels/bus_panel.cpp" line="+41"/>
        <location line="+49"/>
        <source>Reconnect</source>
        <translation>Neu verbinden</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>CAN bus and nodes</source>
        <translation>CAN-Bus und Knoten</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMT</source>
        <translation>NMT</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CiA 402</source>
        <translation>CiA 402</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>HB ms</source>
        <translation>HB ms</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>down</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>connecting</source>
        <translation>verbindet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>up</source>
        <translation>bereit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>lost</source>
        <translation>verloren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Bus %1</source>
        <translation>Bus %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>BUS UP - %1 OF %2 NODES SILENT</source>
        <translation>BUS UP - %1 VON %2 KNOTEN STUMM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No heartbeat within %1 ms from node(s) %2: check their power and cable.</source>
        <translation>Kein Heartbeat innerhalb %1 ms von Knoten %2: Spannungsversorgung und Kabel prüfen.</translation>
    </message>
    <message>
        <location line="-25"/>
        <location line="+58"/>
        <source>none</source>
        <translation>aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&gt;9999</source>
        <translation>&gt;9999</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>node %1, axis %2</source>
        <translation>Knoten %1, Achse %2</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::CellViewPanel</name>
    <message>
        <location filename="../../ui/panels/monitor_views.cpp" line="+32"/>
        <source>3D view not built in this configuration.</source>
        <translation>3D-Ansicht in dieser Konfiguration nicht verfügbar.</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::ConsumablesPanel</name>
    <message>
        <location filename="../../ui/panels/consumables_panel.cpp" line="+40"/>
        <source>New consumables fitted...</source>
        <translation>Neue Verschleißteile eingesetzt...</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Fitted</source>
        <translation>Eingesetzt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Removed</source>
        <translation>Entnommen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cuts</source>
        <translation>Schnitte</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pierces</source>
        <translation>Einstiche</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Arc-on [min]</source>
        <translation>Lichtbogen an [min]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cut length [m]</source>
        <translation>Schnittlänge [m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Removed by, why</source>
        <translation>Entnommen von, Grund</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>New consumables fitted</source>
        <translation>Neue Verschleißteile eingesetzt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Why were they changed (worn nozzle, electrode pit depth, cut quality)?</source>
        <translation>Warum wurden sie gewechselt (Düse verschlissen, Elektrodenabbrand, Schnittqualität)?</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>No production record: consumables are not counted (--record off, or the record could not be opened).</source>
        <translation>Kein Produktionsprotokoll: Verschleißteile werden nicht gezählt (--record off, oder das Protokoll ließ sich nicht öffnen).</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The job cuts without a cut chart (Cut page): no consumable set to count.</source>
        <translation>Der Auftrag schneidet ohne Schneidtabelle (Seite Schnitt): kein Verschleißteilsatz zu zählen.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Consumable set: %1 (fitted %2)</source>
        <translation>Verschleißteilsatz: %1 (eingesetzt %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 cuts, %2 pierces, arc-on %3 min, cut length %4 m</source>
        <translation>%1 Schnitte, %2 Einstiche, Lichtbogen an %3 min, Schnittlänge %4 m</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>ALARM: expected life reached, change the consumables (%1)</source>
        <translation>ALARM: erwartete Standzeit erreicht, Verschleißteile wechseln (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Warning: 90 % of the expected life used (%1)</source>
        <translation>Warnung: 90 % der erwarteten Standzeit verbraucht (%1)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>in the torch</source>
        <translation>im Brenner</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>All sets: %1 installations, %2 cuts, %3 pierces, arc-on %4 min, %5 m</source>
        <translation>Alle Sätze: %1 Einsätze, %2 Schnitte, %3 Einstiche, Lichtbogen an %4 min, %5 m</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The consumable statistics cannot be read: %1</source>
        <translation>Die Verschleißteilstatistik kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No consumable set to replace (no record, or no cut chart in the job).</source>
        <translation>Kein Verschleißteilsatz zu ersetzen (kein Protokoll oder keine Schneidtabelle im Auftrag).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Say why the consumables were changed: the record keeps it.</source>
        <translation>Geben Sie an, warum die Verschleißteile gewechselt wurden: das Protokoll hält es fest.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Not recorded: %1</source>
        <translation>Nicht erfasst: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>New consumables recorded: the counts start from zero.</source>
        <translation>Neue Verschleißteile erfasst: die Zähler beginnen bei null.</translation>
    </message>
    <message>
        <location filename="../../app/gui/station_access.cpp" line="+89"/>
        <source>Consumables</source>
        <translation>Verschleißteile</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::ControlPanel</name>
    <message>
        <location filename="../../ui/panels/control_panel.cpp" line="+29"/>
        <source>%1: EMERGENCY STOP (works from any field, also in dialogs)
%2: Enable
%3: Home
%4: Reset
%5: Release E-STOP
</source>
        <translation>%1: NOT-HALT (wirkt aus jedem Feld, auch in Dialogen)
%2: Freigeben
%3: Referenzieren
%4: Reset
%5: NOT-HALT entriegeln
</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: Start
%2: Feed hold
%3: Resume
%4: Abort (press twice within %5 s)
</source>
        <translation>%1: Start
%2: Vorschub halt
%3: Fortsetzen
%4: Abbruch (innerhalb %5 s zweimal drücken)
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 / %2: speed override -%3 % / +%3 %
F12: acknowledge the alarms
Ctrl+N / Ctrl+O / Ctrl+S: job files</source>
        <translation>%1 / %2: Geschwindigkeits-Override -%3 % / +%3 %
F12: Alarme quittieren
Ctrl+N / Ctrl+O / Ctrl+S: Auftragsdateien</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>EMERGENCY
STOP  [%1]</source>
        <translation>NOT-HALT
[%1]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torch off and drives disabled at once; latched until released and Reset. Shortcut %1 works from any field.</source>
        <translation>Brenner aus und Antriebe sofort gesperrt; bleibt verriegelt bis zum Entriegeln und Reset. Tastenkürzel %1 wirkt aus jedem Feld.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Enable</source>
        <translation>Freigeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Feed hold</source>
        <translation>Halt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Decelerates along the path and holds there [%1]</source>
        <translation>Bremst entlang der Bahn ab und hält dort an [%1]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Continues the cut from where it held [%1]</source>
        <translation>Setzt den Schnitt dort fort, wo er angehalten wurde [%1]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort</source>
        <translation>Abbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Release
E-STOP</source>
        <translation>NOT-HALT
entriegeln</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stops the cut along the path with the torch off. Press twice: the first press asks, the second (within %1 s) aborts.</source>
        <translation>Stoppt den Schnitt entlang der Bahn bei ausgeschaltetem Brenner. Zweimal drücken: der erste Druck fragt nach, der zweite (innerhalb %1 s) bricht ab.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The emergency stop button was pulled back out (the hazard is gone). Reset then clears the latch [%1].</source>
        <translation>Der NOT-HALT-Taster wurde wieder herausgezogen (die Gefahr ist beseitigt). Reset hebt danach die Verriegelung auf [%1].</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Clears a fault, or an emergency stop once it is released [%1].</source>
        <translation>Setzt einen Fehler zurück, oder einen NOT-HALT, sobald er entriegelt ist [%1].</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Enables the drives (and connects the CAN bus) [%1]</source>
        <translation>Gibt die Antriebe frei (und verbindet den CAN-Bus) [%1]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves every axis to its reference at the job&apos;s home speed [%1]</source>
        <translation>Fährt alle Achsen mit der Referenziergeschwindigkeit des Auftrags auf ihren Referenzpunkt [%1]</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Speed override [%1 -, %2 +]</source>
        <translation>Geschw.-Override [%1 -, %2 +]</translation>
    </message>
    <message>
        <location line="+128"/>
        <source>Press again to ABORT  [%1]</source>
        <translation>Erneut drücken: ABBRUCH  [%1]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort  [%1]</source>
        <translation>Abbruch  [%1]</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>E-STOP pressed: remove the hazard, then Release E-STOP and Reset.</source>
        <translation>NOT-HALT betätigt: Gefahr beseitigen, dann NOT-HALT entriegeln und Reset.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start: %1</source>
        <translation>Start: %1</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::ControllerForm</name>
    <message>
        <location filename="../../ui/machines/pipe_robot/controller_form.cpp" line="+63"/>
        <location line="+193"/>
        <source>0 chuck</source>
        <translation>0 Futter</translation>
    </message>
    <message>
        <location line="-193"/>
        <location line="+193"/>
        <source>1 base</source>
        <translation>1 Basis</translation>
    </message>
    <message>
        <location line="-193"/>
        <location line="+193"/>
        <source>2 shoulder</source>
        <translation>2 Schulter</translation>
    </message>
    <message>
        <location line="-192"/>
        <location line="+193"/>
        <source>3 elbow</source>
        <translation>3 Ellbogen</translation>
    </message>
    <message>
        <location line="-193"/>
        <location line="+193"/>
        <source>4 wrist</source>
        <translation>4 Handgelenk</translation>
    </message>
    <message>
        <location line="-193"/>
        <location line="+193"/>
        <source>5 roll</source>
        <translation>5 Rollachse</translation>
    </message>
    <message>
        <location line="-190"/>
        <source>link %1</source>
        <translation>Glied %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PID with first-order filter, per joint</source>
        <translation>PID mit Filter 1. Ordnung, je Gelenk</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>C(s) = (Kd s + Kp + Ki/s) / (tau_f s + 1); output in N m.</source>
        <translation>C(s) = (Kd s + Kp + Ki/s) / (tau_f s + 1); Ausgang in N m.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tune (SIMC)</source>
        <translation>Einstellen (SIMC)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Kp, Ki and Kd of every joint by Skogestad&apos;s SIMC rules (tight: tau_c = theta) from the joint&apos;s inertia and viscous friction: the rigid-body model at the cut&apos;s mean pose, or the linear plant rows. tau_f stays.</source>
        <translation>Kp, Ki und Kd jedes Gelenks nach Skogestads SIMC-Regeln (straff: tau_c = theta) aus Trägheit und viskoser Reibung des Gelenks: das Starrkörpermodell in der mittleren Stellung des Schnitts oder die Zeilen der linearen Strecke. tau_f bleibt.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Mechanics of the simulated drives</source>
        <translation>Mechanik der simulierten Antriebe</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rigid body</source>
        <translation>Starrkörper</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Linear plant</source>
        <translation>Lineare Strecke</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Plant model</source>
        <translation>Streckenmodell</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gravity feed-forward</source>
        <translation>Schwerkraft-Vorsteuerung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rigid body: the arm&apos;s links and the drive trains below, coupled. Linear: one inertia and viscous friction per joint.</source>
        <translation>Starrkörper: die Glieder des Arms und die Antriebsstränge unten, gekoppelt. Linear: eine Trägheit und eine viskose Reibung je Gelenk.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Joint plant (linear model)</source>
        <translation>Gelenkstrecke (lineares Modell)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Arm links (rigid-body model)</source>
        <translation>Glieder des Arms (Starrkörpermodell)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Centre of mass in the link&apos;s frame; inertia tensor about the centre of mass, in the same frame.</source>
        <translation>Schwerpunkt im Koordinatensystem des Glieds; Trägheitstensor um den Schwerpunkt, im selben System.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Drive trains (rigid-body model)</source>
        <translation>Antriebsstränge (Starrkörpermodell)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Rotor inertia on the motor side; friction and torque limit on the joint side.</source>
        <translation>Rotorträgheit auf der Motorseite; Reibung und Momentgrenze auf der Gelenkseite.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Chuck (rigid-body model)</source>
        <translation>Futter (Starrkörpermodell)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Chuck inertia</source>
        <translation>Trägheit des Futters</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Pipe density</source>
        <translation>Dichte des Rohrs</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The pipe in the chuck turns with it: the chuck&apos;s inertia adds it.</source>
        <translation>Das Rohr im Futter dreht sich mit: die Trägheit des Futters schließt es ein.</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+24"/>
        <source>Not tuned: %1</source>
        <translation>Nicht eingestellt: %1</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>Not tuned: the job has invalid values; correct the marked fields first.</source>
        <translation>Nicht eingestellt: der Auftrag hat ungültige Werte; zuerst die markierten Felder berichtigen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Tuning: planning the cut for its mean pose...</source>
        <translation>Einstellen: der Schnitt wird für seine mittlere Stellung geplant ...</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Not tuned: the job changed while tuning; tune again.</source>
        <translation>Nicht eingestellt: der Auftrag hat sich beim Einstellen geändert; erneut einstellen.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1: J = %2 kg m², b = %3 N m s/rad, theta = %4 ms, Kc = %5 N m/rad, tau_I = %6 ms, tau_D = %7 ms, gain margin %8</source>
        <translation>%1: J = %2 kg m², b = %3 N m s/rad, theta = %4 ms, Kc = %5 N m/rad, tau_I = %6 ms, tau_D = %7 ms, Amplitudenreserve %8</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>rigid body at the cut&apos;s mean pose</source>
        <translation>Starrkörper in der mittleren Stellung des Schnitts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>linear plant rows</source>
        <translation>Zeilen der linearen Strecke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SIMC gains written (%1): tau_c = theta = %2 ms, gain margin %3 or more.</source>
        <translation>SIMC-Verstärkungen eingetragen (%1): tau_c = theta = %2 ms, Amplitudenreserve %3 oder mehr.</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::CutChartsDialog</name>
    <message>
        <location filename="../../ui/panels/cut_charts_dialog.cpp" line="+53"/>
        <source>Log in to edit the cut charts (needs the %1 level).</source>
        <translation>Zum Bearbeiten der Schneidtabellen anmelden (erfordert die Stufe %1).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Editing the cut charts needs the %1 level (%2 is logged in as %3).</source>
        <translation>Das Bearbeiten der Schneidtabellen erfordert die Stufe %1 (%2 ist als %3 angemeldet).</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Add row</source>
        <translation>Zeile hinzufügen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove row</source>
        <translation>Zeile entfernen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+359"/>
        <source>Cut charts</source>
        <translation>Schneidtabellen</translation>
    </message>
    <message>
        <location line="-355"/>
        <location line="+345"/>
        <source>The user&apos;s table: %1</source>
        <translation>Die Tabelle des Benutzers: %1</translation>
    </message>
    <message>
        <location line="-344"/>
        <source>The shipped table (a save writes the user&apos;s table %1, used from then on).</source>
        <translation>Die mitgelieferte Tabelle (Speichern schreibt die Tabelle des Benutzers %1, die ab dann gilt).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The user&apos;s table %1 cannot be read (%2); fix or remove it. The shipped table is shown.</source>
        <translation>Die Tabelle des Benutzers %1 ist nicht lesbar (%2); korrigieren oder entfernen. Angezeigt wird die mitgelieferte Tabelle.</translation>
    </message>
    <message>
        <location line="+174"/>
        <source>Source: %1</source>
        <translation>Quelle: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No chart for this choice.</source>
        <translation>Keine Schneidtabelle für diese Auswahl.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Read-only: %1</source>
        <translation>Nur lesen: %1</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Changed; Save writes the user&apos;s table.</source>
        <translation>Geändert; Speichern schreibt die Tabelle des Benutzers.</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1 = &apos;%2&apos; is not a number of %3%4</source>
        <translation>%1 = &apos;%2&apos; ist keine Zahl in %3%4</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Select the row to remove.</source>
        <translation>Die zu entfernende Zeile auswählen.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Not saved: %1</source>
        <translation>Nicht gespeichert: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Saved to %1.</source>
        <translation>Gespeichert in %1.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The cut charts have unsaved changes. Save them?</source>
        <translation>Die Schneidtabellen haben ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::CutForm</name>
    <message>
        <location filename="../../ui/forms/cut_form.cpp" line="+20"/>
        <source>Target and bevel</source>
        <translation>Ziel und Fase</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cut</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hole in the main pipe</source>
        <translation>Ausschnitt im Hauptrohr</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>End of the branch pipe</source>
        <translation>Ende des Abzweigrohrs</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bevel angle</source>
        <translation>Fasenwinkel</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Speed</source>
        <translation>Drehzahl</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cutting speed</source>
        <translation>Schnittgeschw.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>From the cut chart (above on this page); set an override there to cut at another speed.</source>
        <translation>Aus der Schneidtabelle (oben auf dieser Seite); dort einen Abweichwert setzen, um mit anderer Geschwindigkeit zu schneiden.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Start / stop ramp</source>
        <translation>Start-/Stopp-Rampe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Path</source>
        <translation>Bahn</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Knot spacing</source>
        <translation>Stützpunktabstand</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Max. torch tilt</source>
        <translation>Max. Brennerneigung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>automatic start point</source>
        <translation>automatischer Startpunkt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start point</source>
        <translation>Startpunkt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start angle phi</source>
        <translation>Startwinkel phi</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::CycleDevicesForm</name>
    <message>
        <location filename="../../ui/forms/cycle_devices_form.cpp" line="+23"/>
        <source>Control cycle</source>
        <translation>Regeltakt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cycle period</source>
        <translation>Taktzeit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulation duration</source>
        <translation>Simulationsdauer</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Safety and feed hold</source>
        <translation>Sicherheit und Vorschub halt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>E-stop category</source>
        <translation>NOT-HALT-Kategorie</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cat 0: torch off, drives off at once</source>
        <translation>Kat. 0: Brenner aus, Antriebe sofort aus</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cat 1: controlled stop, then off</source>
        <translation>Kat. 1: gesteuertes Stillsetzen, dann aus</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Feed hold deceleration</source>
        <translation>Verzögerung Vorschub halt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Torch in feed hold</source>
        <translation>Brenner bei Vorschub halt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>keep the torch on</source>
        <translation>Brenner eingeschaltet lassen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Following error limit, rotary axes</source>
        <translation>Schleppfehlergrenze, Rundachsen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Following error limit, linear axes</source>
        <translation>Schleppfehlergrenze, Linearachsen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Homing speed, rotary axes</source>
        <translation>Referenziergeschw., Rundachsen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Homing speed, linear axes</source>
        <translation>Referenziergeschw., Linearachsen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run records folder</source>
        <translation>Ordner Laufprotokolle</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drives</source>
        <translation>Antriebe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated cell</source>
        <translation>Simulierte Zelle</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CANopen CiA 402</source>
        <translation>CANopen CiA 402</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>CAN plugin</source>
        <translation>CAN-Plugin</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CAN interface</source>
        <translation>CAN-Schnittstelle</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bit rate</source>
        <translation>Bitrate</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Heartbeat timeout</source>
        <translation>Heartbeat-Timeout</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Node ID</source>
        <translation>Knoten-ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Counts/unit</source>
        <translation>Inkr./Einheit</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Counts per degree (rotary axes) or per mm (linear axes).</source>
        <translation>Inkremente pro Grad (Rundachsen) bzw. pro mm (Linearachsen).</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::DecimalField</name>
    <message>
        <location filename="../../ui/forms/number_fields.cpp" line="+54"/>
        <source>takes %1 to %2</source>
        <translation>erlaubt %1 bis %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+56"/>
        <source>&apos;%1&apos; refused: %2 %3</source>
        <translation>&apos;%1&apos; abgelehnt: %2 %3</translation>
    </message>
    <message>
        <location line="-19"/>
        <source>; the previous value is kept</source>
        <translation>; der vorherige Wert bleibt erhalten</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>needs a number</source>
        <translation>erfordert eine Zahl</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>takes no negative numbers</source>
        <translation>erlaubt keine negativen Zahlen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>takes a whole number</source>
        <translation>erlaubt nur ganze Zahlen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>takes one decimal separator (&apos;.&apos; or &apos;,&apos;), no group separators</source>
        <translation>erlaubt ein Dezimaltrennzeichen (&apos;.&apos; oder &apos;,&apos;), keine Tausendertrennzeichen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>takes a sign only in front</source>
        <translation>erlaubt ein Vorzeichen nur am Anfang</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>takes a number (digits, a sign, &apos;.&apos; or &apos;,&apos; as the decimal point)</source>
        <translation>erlaubt nur eine Zahl (Ziffern, ein Vorzeichen, &apos;.&apos; oder &apos;,&apos; als Dezimaltrennzeichen)</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>keeps %n decimal(s)</source>
        <translation>
            <numerusform>erlaubt höchstens %n Nachkommastelle</numerusform>
            <numerusform>erlaubt höchstens %n Nachkommastellen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>takes a finite number</source>
        <translation>erfordert eine endliche Zahl</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::DroPanel</name>
    <message>
        <location filename="../../ui/panels/dro_panel.cpp" line="+33"/>
        <source>Position: commanded / actual</source>
        <translation>Position: Soll / Ist</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The axis to jog</source>
        <translation>Achse für den Tippbetrieb</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>cont.</source>
        <translation>kont.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Jog step in the axis unit (deg or mm); cont.: the axis moves while - or + is held, up to its limit</source>
        <translation>Tippschrittweite in der Achseinheit (deg oder mm); kont.: die Achse fährt, solange - oder + gedrückt ist, bis zu ihrer Grenze</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>axis %1</source>
        <translation>Achse %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 .. %3 %4</source>
        <translation>%1: %2 .. %3 %4</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::EventLogPanel</name>
    <message>
        <location filename="../../ui/panels/event_log_panel.cpp" line="+23"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Severity</source>
        <translation>Klasse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>To clear: remove the hazard, release the E-STOP, press Reset, then Enable.</source>
        <translation>Zum Aufheben: Gefahr beseitigen, NOT-HALT entriegeln, Reset drücken, dann Freigeben.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>To clear: correct the cause named above, press Reset, then Enable and Home.</source>
        <translation>Zum Aufheben: oben genannte Ursache beheben, Reset drücken, dann Freigeben und Referenzieren.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>ERROR</source>
        <translation>FEHLER</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>WARNING</source>
        <translation>WARNUNG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>info</source>
        <translation>Info</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::FlyingSawCarriageSawForm</name>
    <message>
        <location filename="../../ui/machines/flying_saw/flying_saw_forms.cpp" line="+376"/>
        <source>Carriage (five periods: BC, CE, EF, FG-GH-HI)</source>
        <translation>Schlitten (fünf Phasen: BC, CE, EF, FG-GH-HI)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Saw cycle in sync (C → D settle, feeds, half turn, retract)</source>
        <translation>Sägezyklus im Gleichlauf (C → D Einschwingen, Vorschübe, halbe Drehung, Rückzug)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cam table points per 180°</source>
        <translation>Punkte Kurventabelle je 180°</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Blade</source>
        <translation>Sägeblatt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Length gauge after the saw (corrects the encoder scale)</source>
        <translation>Längenmessung nach der Säge (korrigiert die Geberskalierung)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gauge on</source>
        <translation>Messung ein</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reports after</source>
        <translation>Meldet nach</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pieces</source>
        <translation>Stück</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Simulated line and roller</source>
        <translation>Simulierte Linie und Messrolle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed wander ±</source>
        <translation>Geschw.-Schwankung ±</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+5"/>
        <source>of speed</source>
        <translation>der Geschw.</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Speed steps ±</source>
        <translation>Geschw.-Sprünge ±</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Roller slip</source>
        <translation>Rollenschlupf</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>of travel</source>
        <translation>des Wegs</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::FlyingSawFiguresForm</name>
    <message>
        <location filename="../../ui/machines/flying_saw/flying_saw_figures.cpp" line="+57"/>
        <source>the job is not for the flying saw</source>
        <translation>der Auftrag ist nicht für die fliegende Säge</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Plan and simulate the queue</source>
        <translation>Schnittliste planen und simulieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export cam table CSV…</source>
        <translation>Kurventabelle als CSV exportieren…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not simulated yet.</source>
        <translation>Noch nicht simuliert.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Carriage position over one cycle (nominal line speed)</source>
        <translation>Schlittenposition über einen Zyklus (Nenn-Liniengeschwindigkeit)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>s (mm)</source>
        <translation>s (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Carriage velocity</source>
        <translation>Schlittengeschwindigkeit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>v (mm/s)</source>
        <translation>v (mm/s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Carriage acceleration</source>
        <translation>Schlittenbeschleunigung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>a (mm/s²)</source>
        <translation>a (mm/s²)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cam table: radial feed against the turntable angle</source>
        <translation>Kurventabelle: radialer Vorschub über dem Drehtellerwinkel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>turntable θ (deg)</source>
        <translation>Drehteller θ (deg)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>feed (mm)</source>
        <translation>Vorschub (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut length error of every piece (simulated queue)</source>
        <translation>Schnittlängenfehler jedes Stücks (simulierte Schnittliste)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>piece</source>
        <translation>Stück</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>length - ordered (mm)</source>
        <translation>Länge - Soll (mm)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export the cam table</source>
        <translation>Kurventabelle exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cam table written to %1.</source>
        <translation>Kurventabelle in %1 geschrieben.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot plan: %1</source>
        <translation>Planung nicht möglich: %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>feed, blades 1 and 2</source>
        <translation>Vorschub, Blatt 1 und 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>blade tip radius</source>
        <translation>Radius der Blattspitze</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>± tolerance</source>
        <translation>± Toleranz</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>error (tolerance ± %1 mm far outside)</source>
        <translation>Fehler (Toleranz ± %1 mm weit außerhalb)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 pieces measured: error mean %2 mm, std %3 mm, max |e| %4 mm, Cpk %5 (± %6 mm); largest cut spread on the pipe %7 mm.</source>
        <translation>%1 Stück gemessen: Fehler Mittelwert %2 mm, Std.-Abw. %3 mm, max |e| %4 mm, Cpk %5 (± %6 mm); größte Schnittstreuung am Rohr %7 mm.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Not completed: %1</source>
        <translation>Nicht abgeschlossen: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+9"/>
        <source>Cam table not written to %1: %2</source>
        <translation>Kurventabelle nicht in %1 geschrieben: %2</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::FlyingSawTubeLineForm</name>
    <message>
        <location filename="../../ui/machines/flying_saw/flying_saw_forms.cpp" line="-373"/>
        <source>length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>pieces</source>
        <translation>Stückzahl</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The tube leaves the mill continuously; the carriage meets it at each cut position, rides with it while the turntable&apos;s two blades cut, and returns. A length changed in the queue applies from the next piece.</source>
        <translation>Das Rohr verlässt die Schweißanlage kontinuierlich; der Schlitten synchronisiert sich an jeder Schnittposition mit ihm, fährt mit, während die beiden Sägeblätter des Drehtellers schneiden, und fährt zurück. Eine in der Schnittliste geänderte Länge gilt ab dem nächsten Stück.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Tube (cut plane)</source>
        <translation>Rohr (Schnittebene)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Round (D)</source>
        <translation>Rund (D)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Square (a × a)</source>
        <translation>Quadratisch (a × a)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Rectangular (a × b)</source>
        <translation>Rechteckig (a × b)</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Line and measuring roller</source>
        <translation>Linie und Messrolle</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Roller pulses per revolution</source>
        <translation>Rollenimpulse pro Umdrehung</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>pulses/rev</source>
        <translation>Imp./U</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Encoder resolution</source>
        <translation>Geberauflösung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Pieces: the queue of cut lengths</source>
        <translation>Stücke: Schnittliste der Längen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Length (mm)</source>
        <translation>Länge (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Count (pieces)</source>
        <translation>Anzahl (Stück)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Add length</source>
        <translation>Länge hinzufügen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove selected</source>
        <translation>Auswahl entfernen</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Send the queue to the running line (from the next piece)</source>
        <translation>Schnittliste an die laufende Linie senden (ab dem nächsten Stück)</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Not sent: no flying-saw program is loaded.</source>
        <translation>Nicht gesendet: kein Programm für fliegende Säge geladen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Not sent: %1</source>
        <translation>Nicht gesendet: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not sent: the queue is empty.</source>
        <translation>Nicht gesendet: die Schnittliste ist leer.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not sent: the queue has %1 entries; the line takes up to %2.</source>
        <translation>Nicht gesendet: die Schnittliste hat %1 Einträge; die Linie nimmt höchstens %2.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not sent: the previous change is not taken yet (it is, when the carriage is back at its wait position).</source>
        <translation>Nicht gesendet: die vorherige Änderung ist noch nicht übernommen (das geschieht, sobald der Schlitten wieder in seiner Warteposition ist).</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Sent: %1 pieces replace the pieces not begun yet, from the next piece.</source>
        <translation>Gesendet: %1 Stück ersetzen die noch nicht begonnenen Stücke, ab dem nächsten Stück.</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>%1 mm per pulse (π D / pulses)</source>
        <translation>%1 mm pro Impuls (π D / Impulse)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 pieces, %2 m</source>
        <translation>%1 Stück, %2 m</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::HistoryPanel</name>
    <message>
        <location filename="../../ui/panels/history_panel.cpp" line="+97"/>
        <source>every machine</source>
        <translation>jede Maschine</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>every outcome</source>
        <translation>jedes Ergebnis</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>faults</source>
        <translation>Störungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>job name contains</source>
        <translation>Auftragsname enthält</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Started</source>
        <translation>Begonnen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Job</source>
        <translation>Auftrag</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Operator</source>
        <translation>Bediener</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Outcome</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cycle (s)</source>
        <translation>Zyklus (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alarms</source>
        <translation>Alarme</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shift report (CSV)...</source>
        <translation>Schichtbericht (CSV)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shift report (PDF)...</source>
        <translation>Schichtbericht (PDF)...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Since</source>
        <translation>Seit</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Shift report written: %1</source>
        <translation>Schichtbericht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>No production record at this station (--record off).</source>
        <translation>Kein Produktionsprotokoll an dieser Station (--record off).</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The production record cannot be read: %1</source>
        <translation>Das Produktionsprotokoll kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>running</source>
        <translation>läuft</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 run(s), %2 completed, %3 s of cycle time</source>
        <translation>%1 Lauf/Läufe, %2 fertig, %3 s Zykluszeit</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Run %1: %2 on the %3</source>
        <translation>Lauf %1: %2 auf %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Operator: %1</source>
        <translation>Bediener: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Started %1, ended %2</source>
        <translation>Begonnen %1, beendet %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outcome: %1, cycle time %2 s</source>
        <translation>Ergebnis: %1, Zykluszeit %2 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Made: %1</source>
        <translation>Gefertigt: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopped at: %1</source>
        <translation>Angehalten bei: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Job fingerprint: %1</source>
        <translation>Auftrags-Fingerabdruck: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run log: %1</source>
        <translation>Laufprotokoll: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Alarms: %1</source>
        <translation>Alarme: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Alarms cannot be read: %1</source>
        <translation>Alarme können nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+29"/>
        <location line="+12"/>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="-215"/>
        <location line="+183"/>
        <location line="+26"/>
        <source>Shift report</source>
        <translation>Schichtbericht</translation>
    </message>
    <message>
        <location filename="../../app/gui/station_access.cpp" line="-4"/>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::JobDocument</name>
    <message>
        <location filename="../../ui/job_document.cpp" line="+21"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The job has no file yet: use Save As.</source>
        <translation>Der Auftrag hat noch keine Datei: Speichern unter verwenden.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cannot save %1: %2</source>
        <translation>%1 kann nicht gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::JobForm</name>
    <message>
        <location filename="../../ui/forms/job_form.cpp" line="+273"/>
        <source>Range %1 to %2 %3</source>
        <translation>Bereich %1 bis %2 %3</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::JobInfoForm</name>
    <message>
        <location filename="../../ui/forms/job_info_form.cpp" line="+13"/>
        <source>Job</source>
        <translation>Auftrag</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::JobQueuePanel</name>
    <message>
        <location filename="../../ui/panels/job_queue_panel.cpp" line="+18"/>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link settings…</source>
        <translation>Verbindung einstellen…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Job</source>
        <translation>Auftrag</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>From</source>
        <translation>Von</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Received</source>
        <translation>Empfangen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Make the selected job the one being edited; check it and press Start.</source>
        <translation>Den gewählten Auftrag zum bearbeiteten machen; prüfen und Start drücken.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shop floor: off (no configuration; cutcell --shopfloor FILE)</source>
        <translation>Fertigungsleitebene: aus (keine Konfiguration; cutcell --shopfloor DATEI)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The shop-floor link&apos;s broker, identity and TLS files</source>
        <translation>Broker, Kennung und TLS-Dateien der Werkstattverbindung</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Select a queued job first.</source>
        <translation>Zuerst einen Auftrag in der Warteschlange wählen.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Not opened: %1</source>
        <translation>Nicht geöffnet: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Opened &apos;%1&apos; from %2: check it, then press Start.</source>
        <translation>&apos;%1&apos; von %2 geöffnet: prüfen, dann Start drücken.</translation>
    </message>
    <message>
        <location filename="../../app/gui/shopfloor_station.cpp" line="+195"/>
        <source>Job queue</source>
        <translation>Auftragswarteschlange</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shop floor: off</source>
        <translation>Fertigungsleitebene: aus</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Shop floor: %1</source>
        <translation>Fertigungsleitebene: %1</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::LinkControl</name>
    <message>
        <location filename="../../ui/link_control.cpp" line="+41"/>
        <source>Enable: bringing the CAN bus up first (%1); the drives are enabled once every node is operational.</source>
        <translation>Freigeben: zuerst wird der CAN-Bus hochgefahren (%1); die Antriebe werden freigegeben, sobald alle Knoten betriebsbereit (Operational) sind.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Enable cancelled: the drives stay disabled when the bus comes up.</source>
        <translation>Freigeben abgebrochen: die Antriebe bleiben gesperrt, wenn der Bus hochkommt.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The CAN bus is already being connected.</source>
        <translation>Der CAN-Bus wird bereits verbunden.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reconnecting the CAN bus (%1).</source>
        <translation>CAN-Bus wird neu verbunden (%1).</translation>
    </message>
    <message>
        <location line="+29"/>
        <location line="+18"/>
        <source>CAN bus: %1</source>
        <translation>CAN-Bus: %1</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>CAN bus %1</source>
        <translation>CAN-Bus %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1. The connection is closed and the port released: check the drives and the bus, then press Enable to try again.</source>
        <translation>%1. Die Verbindung ist geschlossen und der Port freigegeben: Antriebe und Bus prüfen, dann Freigeben drücken, um es erneut zu versuchen.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1. Drives that were enabled are in Fault. Press Reconnect (bus box) or Reset, then Enable.</source>
        <translation>%1. Freigegebene Antriebe sind im Fehlerzustand. Neu verbinden (Bus-Feld) oder Reset drücken, dann Freigeben.</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::LoginPanel</name>
    <message>
        <location filename="../../ui/panels/login_panel.cpp" line="+14"/>
        <source>Log in</source>
        <translation>Anmelden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Log out</source>
        <translation>Abmelden</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>User</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Password</source>
        <translation>Passwort</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not logged in: E-STOP and feed hold work for everyone</source>
        <translation>Nicht angemeldet: NOT-HALT und Vorschub-Halt wirken für alle</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::MainWindow</name>
    <message>
        <location filename="../../ui/main_window.cpp" line="+157"/>
        <source>Event log</source>
        <translation>Ereignisprotokoll</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+214"/>
        <source>Alarms</source>
        <translation>Alarme</translation>
    </message>
    <message>
        <location line="-213"/>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Idle</source>
        <translation>Inaktiv</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no machine yet</source>
        <translation>noch keine Maschine</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>planning %p %</source>
        <translation>Planung %p %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancel planning</source>
        <translation>Planung abbrechen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>E-STOP: %1 (any field)</source>
        <translation>NOT-HALT: %1 (aus jedem Feld)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New...</source>
        <translation>&amp;Neu...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open job</source>
        <translation>Auftrag öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CutCell jobs (*.json);;All files (*)</source>
        <translation>CutCell-Aufträge (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save &amp;as...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export plots as PNG...</source>
        <translation>Diagramme als PNG exportieren...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export plots</source>
        <translation>Diagramme exportieren</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export plot data as CSV...</source>
        <translation>Diagrammdaten als CSV exportieren...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export data</source>
        <translation>Daten exportieren</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export alarms as CSV...</source>
        <translation>Alarme als CSV exportieren...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export alarms</source>
        <translation>Alarme exportieren</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>clear the %1 first (Release E-STOP, Reset)</source>
        <translation>zuerst %1 aufheben (NOT-HALT entriegeln, Reset)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the machine is moving (%1): stop it first</source>
        <translation>die Maschine fährt (%1): zuerst anhalten</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>This run starts at a speed override of %1 %.</source>
        <translation>Dieser Lauf startet mit einem Geschwindigkeits-Override von %1 %.</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Alarms (%1)</source>
        <translation>Alarme (%1)</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>cycle %1 ms, jitter p99 %2 us, overruns %3</source>
        <translation>Zyklus %1 ms, Jitter p99 %2 us, Überläufe %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>, E-STOP latency %1 us</source>
        <translation>, NOT-HALT-Latenz %1 us</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Parameters are locked while the machine moves.</source>
        <translation>Parameter sind gesperrt, solange die Maschine verfährt.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1[*] - CutCell</source>
        <translation>%1[*] - CutCell</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Clear list</source>
        <translation>Liste leeren</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Speed override set back to 100 % after the %1 (was %2 %).</source>
        <translation>Geschwindigkeits-Override nach %1 auf 100 % zurückgesetzt (war %2 %).</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Cannot open the job</source>
        <translation>Auftrag kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+7"/>
        <source>Cannot import the file</source>
        <translation>Datei kann nicht importiert werden</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Cannot import %1: %2</source>
        <translation>%1 kann nicht importiert werden: %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Imported %1 as a new job (%2 report lines); save it to keep it.</source>
        <translation>%1 als neuer Auftrag importiert (%2 Berichtszeilen); zum Behalten speichern.</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Cannot import the files: %1</source>
        <translation>Die Dateien können nicht importiert werden: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot import the files</source>
        <translation>Die Dateien können nicht importiert werden</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: refused: %2</source>
        <translation>%1: abgelehnt: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Imported %1 of %2 file(s) into %3 (import-report.csv)</source>
        <translation>%1 von %2 Datei(en) nach %3 importiert (import-report.csv)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No file was imported.</source>
        <translation>Keine Datei wurde importiert.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Folder for the %1 imported jobs</source>
        <translation>Ordner für die %1 importierten Aufträge</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>No machine &quot;%1&quot; in this build.</source>
        <translation>Keine Maschine &quot;%1&quot; in dieser Programmversion.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No new job for the %1: %2</source>
        <translation>Kein neuer Auftrag für %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No default job for the %1: %2</source>
        <translation>Kein Standardauftrag für %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New job for the %1.</source>
        <translation>Neuer Auftrag für %1.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is an example shipped with CutCell or a read-only file: Save writes a copy (Save As).</source>
        <translation>%1 ist ein mit CutCell geliefertes Beispiel oder eine schreibgeschützte Datei: Speichern legt eine Kopie an (Speichern unter).</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+18"/>
        <source>Cannot save the job</source>
        <translation>Auftrag kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location line="-15"/>
        <location line="+18"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Save job</source>
        <translation>Auftrag speichern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CutCell jobs (*.json)</source>
        <translation>CutCell-Aufträge (*.json)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The job &quot;%1&quot; has unsaved changes. Save them?</source>
        <translation>Der Auftrag &quot;%1&quot; hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Machine in motion</source>
        <translation>Maschine in Bewegung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The machine is %1. Quitting stops it at once (emergency stop). Quit?</source>
        <translation>Maschinenzustand: %1. Beenden stoppt die Maschine sofort (NOT-HALT). Beenden?</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::MethodComparisonForm</name>
    <message>
        <location filename="../../ui/machines/pipe_robot/method_comparison_page.cpp" line="+32"/>
        <source>static pipe</source>
        <translation>stehendes Rohr</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rotating pipe</source>
        <translation>drehendes Rohr</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Compare methods</source>
        <translation>Verfahren vergleichen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plans and simulates the job&apos;s cut with the pipe static and with the pipe turning (seed 000, Fig. 11-14).</source>
        <translation>Plant und simuliert den Schnitt des Auftrags mit stehendem und mit drehendem Rohr (Seed 000, Abb. 11-14).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Compare the job&apos;s cut with the pipe static and with the pipe turning: joint errors and the torch tip&apos;s error over time.</source>
        <translation>Vergleicht den Schnitt des Auftrags mit stehendem und mit drehendem Rohr: Gelenkfehler und Fehler der Brennerspitze über der Zeit.</translation>
    </message>
    <message>
        <location line="+150"/>
        <source>Joint errors, %1</source>
        <translation>Gelenkfehler, %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+2"/>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>commanded - actual (deg)</source>
        <translation>Soll - Ist (deg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tip position error, %1</source>
        <translation>Positionsfehler der Spitze, %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FK(actual) - FK(commanded) (mm)</source>
        <translation>FK(Ist) - FK(Soll) (mm)</translation>
    </message>
    <message>
        <location line="-77"/>
        <source>a comparison is running</source>
        <translation>ein Vergleich läuft</translation>
    </message>
    <message>
        <location line="-70"/>
        <source>Max |joint error| (deg) and the tip error&apos;s range min … max (mm, robot base frame), over every cycle:</source>
        <translation>Max. |Gelenkfehler| (deg) und Bereich des Spitzenfehlers min. … max. (mm, Roboter-Basissystem), über alle Zyklen:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Static</source>
        <translation>Stehend</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Rotating</source>
        <translation>Drehend</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ratio</source>
        <translation>Verhältnis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pipe static</source>
        <translation>Rohr stehend</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pipe turning</source>
        <translation>Rohr drehend</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rotating / static of the max |error| (n/a where the static figure is zero)</source>
        <translation>Drehend / stehend des max. |Fehlers| (k. A., wo der stehende Wert null ist)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Joint 0 (chuck)</source>
        <translation>Gelenk 0 (Futter)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tip %1</source>
        <translation>Spitze %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Figures of the static pipe (Fig. 11, 13)</source>
        <translation>Diagramme des stehenden Rohrs (Abb. 11, 13)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Figures of the rotating pipe (Fig. 12, 14)</source>
        <translation>Diagramme des drehenden Rohrs (Abb. 12, 14)</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Planning and simulating both methods ...</source>
        <translation>Beide Verfahren werden geplant und simuliert ...</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The comparison was cancelled.</source>
        <translation>Der Vergleich wurde abgebrochen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 s simulated at %3 ms per cycle</source>
        <translation>%1: %2 s simuliert mit %3 ms je Zyklus</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: not simulated - %2</source>
        <translation>%1: nicht simuliert - %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>n/a</source>
        <translation>k. A.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::MethodForm</name>
    <message>
        <location filename="../../ui/machines/pipe_robot/method_form.cpp" line="+33"/>
        <source>Cutting method</source>
        <translation>Schneidverfahren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rotating pipe</source>
        <translation>Drehendes Rohr</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Static pipe</source>
        <translation>Stehendes Rohr</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Method</source>
        <translation>Verfahren</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Chuck angle (static)</source>
        <translation>Futterwinkel (stehend)</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::ParameterTabs</name>
    <message>
        <location filename="../../ui/forms/parameter_tabs.cpp" line="+78"/>
        <source>Job</source>
        <translation>Auftrag</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pipes</source>
        <translation>Rohre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cycle &amp;&amp; devices</source>
        <translation>Zyklus &amp;&amp; Geräte</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>This machine has no linear axis.</source>
        <translation>Diese Maschine hat keine Linearachse.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This machine has no rotary axis.</source>
        <translation>Diese Maschine hat keine Rundachse.</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::PipesForm</name>
    <message>
        <location filename="../../ui/forms/pipes_form.cpp" line="+21"/>
        <source>Outer radius</source>
        <translation>Außenradius</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Wall thickness</source>
        <translation>Wandstärke</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Main pipe (run)</source>
        <translation>Hauptrohr (Durchgang)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Branch pipe</source>
        <translation>Abzweigrohr</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Intersection</source>
        <translation>Verschneidung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Angle between axes</source>
        <translation>Winkel zwischen Achsen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Eccentricity</source>
        <translation>Exzentrizität</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::PlotsPanel</name>
    <message>
        <location filename="../../ui/panels/monitor_views.cpp" line="+88"/>
        <source>Tracking plots not built in this configuration.</source>
        <translation>Diagramme der Bahnverfolgung sind in dieser Konfiguration nicht enthalten.</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>arc voltage</source>
        <translation>Lichtbogenspannung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>standoff error</source>
        <translation>Abstandsfehler</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>THC correction</source>
        <translation>THC-Korrektur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>arc voltage (V)</source>
        <translation>Lichtbogenspannung (V)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torch height (mm)</source>
        <translation>Brennerhöhe (mm)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cartesian error (mm)</source>
        <translation>Kartesischer Fehler (mm)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>torch miss on the pipe</source>
        <translation>Brennerabweichung am Rohr</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>miss (mm)</source>
        <translation>Abweichung (mm)</translation>
    </message>
    <message>
        <location line="+78"/>
        <location line="+10"/>
        <source>plots not built</source>
        <translation>Diagramme nicht enthalten</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::ProcessForm</name>
    <message>
        <location filename="../../ui/forms/process_form.cpp" line="+42"/>
        <source>Plasma</source>
        <translation>Plasma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Oxy-fuel</source>
        <translation>Autogen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Laser</source>
        <translation>Laser</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+83"/>
        <source>Thickness</source>
        <translation>Dicke</translation>
    </message>
    <message>
        <location line="-81"/>
        <source>Kerf width</source>
        <translation>Schnittfugenbreite</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cut speed</source>
        <translation>Schneidgeschwindigkeit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pierce height</source>
        <translation>Einstechhöhe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pierce delay</source>
        <translation>Einstechzeit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cut height</source>
        <translation>Schneidhöhe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Arc voltage</source>
        <translation>Lichtbogenspannung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Preheat</source>
        <translation>Vorwärmen</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Cut chart</source>
        <translation>Schneidtabelle</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>use a cut chart</source>
        <translation>Schneidtabelle verwenden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cut charts…</source>
        <translation>Schneidtabellen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>View and edit the cut-chart library (the user&apos;s table; the setter level and above may edit it).</source>
        <translation>Schneidtabellen ansehen und bearbeiten (die Tabelle des Benutzers; bearbeiten ab der Stufe Einrichter).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Process data</source>
        <translation>Prozessdaten</translation>
    </message>
    <message>
        <location line="+12"/>
        <location filename="../../ui/panels/cut_charts_dialog.cpp" line="-306"/>
        <source>Process</source>
        <translation>Prozess</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../../ui/panels/cut_charts_dialog.cpp" line="+1"/>
        <source>Material</source>
        <translation>Werkstoff</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../../ui/panels/cut_charts_dialog.cpp" line="+1"/>
        <source>Consumable set</source>
        <translation>Verschleißteilsatz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the part&apos;s wall</source>
        <translation>Wand des Werkstücks</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Thickness from</source>
        <translation>Dicke aus</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Figures at this thickness</source>
        <translation>Werte bei dieser Dicke</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Figure</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Chart</source>
        <translation>Tabelle</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Override</source>
        <translation>Abweichend</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Used</source>
        <translation>Verwendet</translation>
    </message>
    <message>
        <location line="+207"/>
        <source>not in the chart</source>
        <translation>nicht in der Tabelle</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Override: saved with the job in place of the chart&apos;s figure.</source>
        <translation>Abweichwert: wird mit dem Auftrag statt des Tabellenwerts gespeichert.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The chart&apos;s figure; tick Override to set another.</source>
        <translation>Der Tabellenwert; Abweichend ankreuzen, um einen anderen zu setzen.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>No cut chart: the cut runs at the Cut page&apos;s speed, without kerf compensation.</source>
        <translation>Keine Schneidtabelle: der Schnitt läuft mit der Geschwindigkeit der Seite Schnitt, ohne Schnittfugenkorrektur.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Not usable: %1</source>
        <translation>Nicht verwendbar: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Chart: %1 at %2 mm%3.</source>
        <translation>Tabelle: %1 bei %2 mm%3.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (the part&apos;s wall)</source>
        <translation> (Wand des Werkstücks)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Source: %1%2.</source>
        <translation>Quelle: %1%2.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (typical values)</source>
        <translation> (typische Werte)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Expected consumable life: %1 pierces, %2 min arc-on.</source>
        <translation>Erwartete Standzeit der Verschleißteile: %1 Einstiche, %2 min Lichtbogen an.</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No kerf width: the torch runs on the part&apos;s edge (tick Override on Kerf width to compensate).</source>
        <translation>Keine Schnittfugenbreite: der Brenner fährt auf der Werkstückkante (bei Schnittfugenbreite Abweichend ankreuzen, um zu korrigieren).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The user&apos;s cut charts are not used: %1</source>
        <translation>Die Schneidtabellen des Benutzers werden nicht verwendet: %1</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::ProfileCutterForm</name>
    <message>
        <location filename="../../ui/machines/profile_cutter/profile_cutter_form.cpp" line="+25"/>
        <source>2-axis NC profile cutter: the pipe turns in the chuck (A), the torch rides the X carriage. Stepper axes behind a pulse card.</source>
        <translation>2-Achsen-NC-Rohrprofilschneider: Das Rohr dreht sich im Futter (A), der Brenner fährt auf dem X-Schlitten. Schrittmotorachsen, angesteuert über eine Impulskarte.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A axis (pipe turn)</source>
        <translation>A-Achse (Rohrdrehung)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>X axis (torch carriage)</source>
        <translation>X-Achse (Brennerschlitten)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Pulse card and torch</source>
        <translation>Impulskarte und Brenner</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Hole in the main pipe</source>
        <translation>Loch im Hauptrohr</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>middle of the main pipe</source>
        <translation>Mitte des Hauptrohrs</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Branch position</source>
        <translation>Abzweigposition</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::ProgressPanel</name>
    <message>
        <location filename="../../ui/panels/progress_panel.cpp" line="+40"/>
        <source>Elapsed</source>
        <translation>Verstrichen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remaining</source>
        <translation>Verbleibend</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Stopped (%1) at %2, %3 after Start</source>
        <translation>Gestoppt (%1) bei %2, %3 nach Start</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Last cycle %1   %2 %3</source>
        <translation>Letzter Zyklus %1   %2 %3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Last run completed.</source>
        <translation>Letzter Lauf abgeschlossen.</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Approach to the start position: %1 %</source>
        <translation>Anfahren der Startposition: %1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>At the start position: the run starts</source>
        <translation>In Startposition: Lauf beginnt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Approach to the first cut point: %1 %</source>
        <translation>Anfahren des ersten Schnittpunkts: %1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Arc on: the cut starts</source>
        <translation>Lichtbogen ein: Schnitt beginnt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>At the first cut point: settling, then the arc</source>
        <translation>Am ersten Schnittpunkt: Einschwingen, dann Lichtbogen</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Idle</source>
        <translation>Inaktiv</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::QuickReturnControllerForm</name>
    <message>
        <location filename="../../ui/machines/quick_return/quick_return_form.cpp" line="+99"/>
        <source>Experiment and control law</source>
        <translation>Experiment und Regelgesetz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Experiment</source>
        <translation>Experiment</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cutting (constant velocity over the workpiece)</source>
        <translation>Schneiden (konstante Geschwindigkeit über dem Werkstück)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tracking y_d = offset + amplitude sin(ω t)</source>
        <translation>Folgeregelung y_d = Offset + Amplitude sin(ω t)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Controller</source>
        <translation>Regler</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>FFC (feed-forward + PD)</source>
        <translation>FFC (Vorsteuerung + PD)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>LQT</source>
        <translation>LQT</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SMC</source>
        <translation>SMC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OSMC (optimal sliding mode)</source>
        <translation>OSMC (optimaler Sliding Mode)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Jacobian</source>
        <translation>Jacobi-Matrix</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Compensator (Eq. 33, K_ρ)</source>
        <translation>Kompensator (Gl. 33, K_ρ)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Exact ρ_y of the model</source>
        <translation>Exaktes ρ_y des Modells</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>FFC (Eq. 37-38)</source>
        <translation>FFC (Gl. 37-38)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>LQT (Eq. 39): Q = diag(q1, q2), R</source>
        <translation>LQT (Gl. 39): Q = diag(q1, q2), R</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>SMC: s = c e + ė, boundary layer φ</source>
        <translation>SMC: s = c e + ė, Grenzschicht φ</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>OSMC (Eq. 20-33): Q = [q11 q12; q12 q22], λ, k1, k2</source>
        <translation>OSMC (Gl. 20-33): Q = [q11 q12; q12 q22], λ, k1, k2</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::QuickReturnFiguresForm</name>
    <message>
        <location filename="../../ui/machines/quick_return/quick_return_figures.cpp" line="+53"/>
        <source>Simulate the cut offline (experiment 2, the job&apos;s controller)</source>
        <translation>Schnitt offline simulieren (Experiment 2, Regler des Auftrags)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Figures of the last run on the engine appear here while it runs; or simulate the job&apos;s cut offline.</source>
        <translation>Diagramme des letzten Laufs in der Steuerung erscheinen hier, während er läuft; oder den Schnitt des Auftrags offline simulieren.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No run and no simulation yet.</source>
        <translation>Noch kein Lauf und keine Simulation.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Velocity profile</source>
        <translation>Geschwindigkeitsprofil</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <source>y&apos; (m/s)</source>
        <translation>y&apos; (m/s)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Phase diagram</source>
        <translation>Phasendiagramm</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <location line="+77"/>
        <location line="+62"/>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <location line="-139"/>
        <source>Velocity error in the work</source>
        <translation>Geschwindigkeitsfehler im Werkstück</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+77"/>
        <location line="+62"/>
        <source>y_d&apos; - y&apos; (m/s)</source>
        <translation>y_d&apos; - y&apos; (m/s)</translation>
    </message>
    <message>
        <location line="-96"/>
        <source>a simulation is running</source>
        <translation>eine Simulation läuft</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot simulate: %1</source>
        <translation>Simulation nicht möglich: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Simulating the cut with %1 ...</source>
        <translation>Schnitt wird mit %1 simuliert ...</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+62"/>
        <source>Velocity error in the work: max %1, RMS %2 m/s</source>
        <translation>Geschwindigkeitsfehler im Werkstück: max. %1, RMS %2 m/s</translation>
    </message>
    <message>
        <location line="-58"/>
        <source>Source: offline simulation of the job&apos;s cut (core runCutting, the engine&apos;s control law on the crank plant).</source>
        <translation>Quelle: Offline-Simulation des Schnitts des Auftrags (Kern runCutting, Regelgesetz der Steuerung an der Kurbelstrecke).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 strokes, velocity error in the work max %3 m/s, RMS %4 m/s (%5 samples); peak torque %6 N m.</source>
        <translation>%1: %2 Hübe, Geschwindigkeitsfehler im Werkstück max. %3 m/s, RMS %4 m/s (%5 Messwerte); Spitzenmoment %6 N m.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not completed: %1</source>
        <translation>Nicht abgeschlossen: %1</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Source: run %1 on the engine, live from its telemetry.</source>
        <translation>Quelle: Lauf %1 in der Steuerung, live aus deren Telemetrie.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Source: run %1 on the engine (ended), from its telemetry.</source>
        <translation>Quelle: Lauf %1 in der Steuerung (beendet), aus deren Telemetrie.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 cuts, velocity error in the work [%3, %4] m max %5 m/s, RMS %6 m/s (%7 samples); peak torque %8 N m.</source>
        <translation>%1: %2 Schnitte, Geschwindigkeitsfehler im Werkstück [%3, %4] m max. %5 m/s, RMS %6 m/s (%7 Messwerte); Spitzenmoment %8 N m.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>y&apos;</source>
        <translation>y&apos;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y_d&apos;</source>
        <translation>y_d&apos;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y&apos;(y)</source>
        <translation>y&apos;(y)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y_d&apos;(y)</source>
        <translation>y_d&apos;(y)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y_d&apos; - y&apos;</source>
        <translation>y_d&apos; - y&apos;</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::QuickReturnMechanismForm</name>
    <message>
        <location filename="../../ui/machines/quick_return/quick_return_form.cpp" line="-124"/>
        <source>Inverted Whitworth quick-return mechanism: the crank (O2, r2) drives the rocker through O3; the link r4 from B moves the slider with the tool on the line x = Dx. The crank must turn fully (the loop closes for every angle).</source>
        <translation>Invertiertes Whitworth-Schnellrücklaufgetriebe: Die Kurbel (O2, r2) treibt die Schwinge über O3 an; das Koppelglied r4 von B bewegt den Schlitten mit dem Werkzeug auf der Geraden x = Dx. Die Kurbel muss voll umlaufen (die Schleife schließt sich für jeden Winkel).</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Mechanism (crank frame, y up)</source>
        <translation>Getriebe (Kurbel-KS, y nach oben)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Slider and crank motor</source>
        <translation>Schlitten und Kurbelmotor</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Cutting stroke (experiment 2)</source>
        <translation>Schnitthub (Experiment 2)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Tracking y_d = offset + amplitude sin(ω t) (experiment 1)</source>
        <translation>Folgeregelung y_d = Offset + Amplitude sin(ω t) (Experiment 1)</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::QuickReturnTrackingForm</name>
    <message>
        <location filename="../../ui/machines/quick_return/quick_return_tracking_page.cpp" line="+58"/>
        <source>Run experiment 1 (FFC, LQT, SMC, OSMC)</source>
        <translation>Experiment 1 ausführen (FFC, LQT, SMC, OSMC)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not run yet.</source>
        <translation>Noch nicht ausgeführt.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: y and y_d</source>
        <translation>%1: y und y_d</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tracking error e = y_d - y</source>
        <translation>Folgefehler e = y_d - y</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>e (mm)</source>
        <translation>e (mm)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Tracking y_d = %1 %2 %3 sin(%4 t) for %5 s without contact force, each controller with the job&apos;s parameters (Controller page); MSE of L e over the last %6 s with L = %7.</source>
        <translation>Folgeregelung y_d = %1 %2 %3 sin(%4 t) über %5 s ohne Kontaktkraft, jeder Regler mit den Parametern des Auftrags (Seite Regler); MSE von L e über die letzten %6 s mit L = %7.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Controller</source>
        <translation>Regler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MSE,
last %1 s</source>
        <translation>MSE,
letzte %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max |e|
(mm)</source>
        <translation>max |e|
(mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>peak torque
(N m)</source>
        <translation>Spitzenmoment
(N m)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>experiment 1 is running</source>
        <translation>Experiment 1 läuft</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot run: %1</source>
        <translation>Ausführung nicht möglich: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Running the four controllers ...</source>
        <translation>Die vier Regler laufen ...</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y_d</source>
        <translation>y_d</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Done in %1 s (off the GUI thread). Lowest MSE: %2 (%3).</source>
        <translation>Fertig in %1 s (außerhalb des GUI-Threads). Kleinster MSE: %2 (%3).</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::RecoveryPanel</name>
    <message>
        <location filename="../../ui/panels/recovery_panel.cpp" line="+26"/>
        <source>Cut recovery</source>
        <translation>Wiederaufnahme</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+2"/>
        <source>Lead-in</source>
        <translation>Anschnitt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The resumed cut starts this far back along the path from the stop point, so the kerf joins (0 .. 50 mm).</source>
        <translation>Der fortgesetzte Schnitt beginnt um diese Strecke entlang der Bahn vor dem Haltepunkt, damit die Schnittfuge anschließt (0 .. 50 mm).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Resume from stop</source>
        <translation>Ab Halt fortsetzen</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+2"/>
        <source>From point</source>
        <translation>Ab Punkt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Run the rest of the cut from this point of the path.</source>
        <translation>Den Rest des Schnitts ab diesem Bahnpunkt ausführen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run from point</source>
        <translation>Ab Punkt starten</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Count the part as good</source>
        <translation>Teil als Gutteil zählen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The run completed, but part of the path was never cut (Run from point). Count the part only if it was finished otherwise.</source>
        <translation>Der Lauf wurde abgeschlossen, aber ein Teil der Bahn wurde nie geschnitten (Ab Punkt starten). Das Teil nur zählen, wenn es anderweitig fertiggestellt wurde.</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>No program loaded.</source>
        <translation>Kein Programm geladen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This machine&apos;s motion follows %1, not a path in time: no cut recovery; start the cycle again.</source>
        <translation>Die Bewegung dieser Maschine folgt %1, nicht einer Bahn über der Zeit: keine Schnitt-Wiederaufnahme; Zyklus neu starten.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the line</source>
        <translation>der Linie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a control law</source>
        <translation>einem Regelgesetz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recovery starts from Ready (state now: %1).</source>
        <translation>Wiederaufnahme startet aus Bereit (Zustand jetzt: %1).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home first: the axes lost their reference.</source>
        <translation>Zuerst referenzieren: Die Achsen haben ihre Referenz verloren.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Part not counted: %1.</source>
        <translation>Teil nicht gezählt: %1.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Stopped at %1.</source>
        <translation>Gestoppt bei %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopped at point %1 / %2, %3 of %4 mm (path time %5 s). Resume starts at %6 s.</source>
        <translation>Gestoppt bei Punkt %1 / %2, %3 von %4 mm (Bahnzeit %5 s). Fortsetzen beginnt bei %6 s.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No stopped cut to recover.</source>
        <translation>Kein gestoppter Schnitt zum Wiederaufnehmen.</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::RobotDhTableForm</name>
    <message>
        <location filename="../../ui/machines/pipe_robot/robot_dh_table_form.cpp" line="+17"/>
        <source>Denavit-Hartenberg table and joint limits</source>
        <translation>Denavit-Hartenberg-Tabelle und Gelenkgrenzen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>0 chuck</source>
        <translation>0 Futter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>1 base</source>
        <translation>1 Basis</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>2 shoulder</source>
        <translation>2 Schulter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>3 elbow</source>
        <translation>3 Ellbogen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>4 wrist</source>
        <translation>4 Handgelenk</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>5 roll</source>
        <translation>5 Rollachse</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Row 0 is the pipe chuck: its d is the distance from the robot base to the cut centre. The analytic inverse kinematics needs the seed arm&apos;s structure (alpha = 90, 0, 0, 90, 0 deg for rows 1..5).</source>
        <translation>Zeile 0 ist das Rohrfutter: Sein d ist der Abstand von der Roboterbasis zur Schnittmitte. Die analytische inverse Kinematik setzt den Aufbau des Standardarms voraus (alpha = 90, 0, 0, 90, 0 deg für Zeilen 1..5).</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::RunController</name>
    <message>
        <location filename="../../ui/run_controller.cpp" line="+75"/>
        <source>Planning cancelled by the operator.</source>
        <translation>Planung vom Bediener abgebrochen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Planning failed: %1</source>
        <translation>Planung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the CAN bus did not come up: %1</source>
        <translation>der CAN-Bus ist nicht hochgefahren: %1</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Path not reachable: %1</source>
        <translation>Bahn nicht erreichbar: %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>machine not available: %1</source>
        <translation>Maschine nicht verfügbar: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no machine: %1</source>
        <translation>keine Maschine: %1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>cannot load the program: %1</source>
        <translation>Programm kann nicht geladen werden: %1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Part not counted as good: %1. Confirm it in the recovery box if it was finished otherwise.</source>
        <translation>Teil nicht als Gutteil gezählt: %1. Falls es anderweitig fertiggestellt wurde, im Feld Wiederaufnahme bestätigen.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>emergency stop</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>abort</source>
        <translation>Abbruch</translation>
    </message>
    <message numerus="yes">
        <location line="+20"/>
        <source>%n invalid field(s) - %1</source>
        <translation>
            <numerusform>%n ungültiges Feld - %1</numerusform>
            <numerusform>%n ungültige Felder - %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>planning the path...</source>
        <translation>Bahn wird geplant...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no plan yet</source>
        <translation>noch keine Planung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>path not reachable - %1</source>
        <translation>Bahn nicht erreichbar - %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the new plan is loaded when the machine is at rest</source>
        <translation>die neue Planung wird im Stillstand der Maschine geladen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no program loaded</source>
        <translation>kein Programm geladen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>drives disabled - press Enable</source>
        <translation>Antriebe gesperrt - Freigeben drücken</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>axes not homed - press Home</source>
        <translation>Achsen nicht referenziert - Referenzieren drücken</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>homing in progress</source>
        <translation>Referenzieren läuft</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>jogging in progress</source>
        <translation>Tippbetrieb läuft</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the cut is running</source>
        <translation>Schnitt läuft</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>feed hold - press Resume or Abort</source>
        <translation>Vorschub halt - Fortsetzen oder Abbruch drücken</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cut completed - press Home to cut again</source>
        <translation>Schnitt beendet - für neuen Schnitt Referenzieren drücken</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>EMERGENCY STOP pressed - release it, then press Reset</source>
        <translation>NOT-HALT betätigt - NOT-HALT entriegeln, dann Reset drücken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EMERGENCY STOP latched - press Reset</source>
        <translation>NOT-HALT gespeichert - Reset drücken</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>fault - CAN bus %1: press Reset (it reconnects the bus), then Enable</source>
        <translation>Störung - CAN-Bus %1: Reset drücken (verbindet den Bus neu), dann Freigeben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fault - see the event log, then press Reset</source>
        <translation>Störung - Ereignisprotokoll prüfen, dann Reset drücken</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>run aborted - press Home to cut again (or resume in the cut recovery box)</source>
        <translation>Ablauf abgebrochen - für neuen Schnitt Referenzieren drücken (oder im Feld Wiederaufnahme fortsetzen)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>drives disabled, CAN bus not connected - press Enable (it connects the bus)</source>
        <translation>Antriebe aus, CAN-Bus nicht verbunden - Freigeben drücken (verbindet den Bus)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>connecting the CAN bus - %1; the drives are enabled when every node is up</source>
        <translation>CAN-Bus wird verbunden - %1; die Antriebe werden freigegeben, sobald alle Knoten bereit sind</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>connecting the CAN bus - %1</source>
        <translation>CAN-Bus wird verbunden - %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN bus not up - %1 - press Enable to try again</source>
        <translation>CAN-Bus nicht bereit - %1 - für neuen Versuch Freigeben drücken</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN bus lost - %1 - press Reconnect or Reset, then Enable</source>
        <translation>CAN-Bus ausgefallen - %1 - Neu verbinden oder Reset drücken, dann Freigeben</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 - bus %2</source>
        <translation>%1 - Bus %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Reconnect refused: the drives are enabled (%1); a reconnection takes their torque away. Abort or stop first.</source>
        <translation>Neu verbinden abgelehnt: die Antriebe sind freigegeben (%1); ein Neuverbinden nimmt ihnen das Moment. Zuerst abbrechen oder anhalten.</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Part counted as good by the operator (%1).</source>
        <translation>Teil vom Bediener als gut gezählt (%1).</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>path time %1 to %2 s not cut</source>
        <translation>Bahnzeit %1 bis %2 s nicht geschnitten</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>points %1 to %2 (%3 mm) never cut</source>
        <translation>Punkte %1 bis %2 (%3 mm) nicht geschnitten</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Reset refused: the EMERGENCY STOP is still pressed (Release E-STOP first).</source>
        <translation>Reset abgelehnt: NOT-HALT ist noch betätigt (zuerst NOT-HALT entriegeln).</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Reset: reconnecting the CAN bus; press Enable when it is up (the bus box shows it).</source>
        <translation>Reset: CAN-Bus wird neu verbunden; Freigeben drücken, sobald er bereit ist (Anzeige im Bus-Feld).</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>EMERGENCY STOP pressed by the operator.</source>
        <translation>NOT-HALT vom Bediener betätigt.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>EMERGENCY STOP released: press Reset to clear the latch.</source>
        <translation>NOT-HALT entriegelt: Reset drücken, um den gespeicherten NOT-HALT zu löschen.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Jog refused: axis %1 is at its limit.</source>
        <translation>Tippen abgelehnt: Achse %1 steht an ihrer Begrenzung.</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>emergency stop during the run</source>
        <translation>NOT-HALT während des Ablaufs</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>fault during the run (see the event log)</source>
        <translation>Störung während des Ablaufs (siehe Ereignisprotokoll)</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::SectionSteelArmsForm</name>
    <message>
        <location filename="../../ui/machines/section_steel/section_steel_arms_form.cpp" line="+41"/>
        <source>Motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>min (deg)</source>
        <translation>min (deg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max (deg)</source>
        <translation>max (deg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>park (deg)</source>
        <translation>Park (deg)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Path arm (3R in the cut plane, joint axes along the bar)</source>
        <translation>Bahnarm (3R in der Schnittebene, Gelenkachsen längs des Stabs)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Link a%1</source>
        <translation>Glied a%1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Groove arm (5-DOF, modified DH; bevel head at the nozzle)</source>
        <translation>Fasenarm (5-achsig, modifiziertes DH; Fasenkopf an der Düse)</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::SectionSteelDrivesForm</name>
    <message>
        <location line="+18"/>
        <source>Simulated drives: a PID on the joint error (torque out, filtered derivative) and a joint plant (inertia, viscous friction, torque limit) per axis. Axes 0..2: path arm, 3..7: groove arm.</source>
        <translation>Simulierte Antriebe: je Achse ein PID-Regler auf den Gelenkfehler (Ausgang Moment, gefilterter D-Anteil) und eine Gelenkstrecke (Trägheit, viskose Reibung, Momentgrenze). Achsen 0..2: Bahnarm, 3..7: Fasenarm.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Kp (N m/rad)</source>
        <translation>Kp (N m/rad)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ki (N m/(rad s))</source>
        <translation>Ki (N m/(rad s))</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kd (N m s/rad)</source>
        <translation>Kd (N m s/rad)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>τ_f (s)</source>
        <translation>τ_f (s)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>J (kg m²)</source>
        <translation>J (kg m²)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>b (N m s/rad)</source>
        <translation>b (N m s/rad)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>τ max (N m)</source>
        <translation>τ max (N m)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Drives: controller</source>
        <translation>Antriebe: Regler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drives: joint plant</source>
        <translation>Antriebe: Gelenkstrecke</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::SectionSteelEndCutForm</name>
    <message>
        <location filename="../../ui/machines/section_steel/section_steel_form.cpp" line="+273"/>
        <source>The end is cut square or mitred (the cut plane turned about the section&apos;s vertical and horizontal axes), then the faces with a groove are bevelled by the groove arm: V = single bevel through the thickness, Y = single bevel with a root face, K = double bevel from both faces with a root face (ISO 9692-1).</source>
        <translation>Das Ende wird rechtwinklig oder auf Gehrung geschnitten (Schnittebene um die senkrechte und waagrechte Achse des Profils gedreht), dann fast der Fasenarm die Flächen mit Fuge an: V = einseitige Fase über die ganze Dicke, Y = einseitige Fase mit Steg, K = Doppelfase von beiden Seiten mit Steg (ISO 9692-1).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Mitre</source>
        <translation>Gehrung</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Groove of the flanges (angles: horizontal leg)</source>
        <translation>Fuge der Flansche (L-Winkel: waagr. Schenkel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Groove of the web (angles: vertical leg)</source>
        <translation>Fuge des Stegs (L-Winkel: senkr. Schenkel)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>none (square)</source>
        <translation>keine (rechtwinklig)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>V</source>
        <translation>V</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Y (with root face)</source>
        <translation>Y (mit Steg)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>K (double bevel)</source>
        <translation>K (Doppelfase)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bevel angle</source>
        <translation>Fasenwinkel</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Root face</source>
        <translation>Steghöhe</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Setup (turning the section over)</source>
        <translation>Aufspannung (Profil wenden)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>1 - as loaded (underside on the conveyor)</source>
        <translation>1 - wie aufgelegt (Unterseite auf Rollgang)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2 - turned over 180° about its long axis</source>
        <translation>2 - um 180° um die Längsachse gewendet</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Setup</source>
        <translation>Aufspannung</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>end_cut.setup - 1: the section as loaded, its underside on the conveyor: the end is cut and every face the torches reach is bevelled. A K groove (double bevel) on the flanges also needs a bevel on the underside of the bottom flange (angles: the horizontal leg), which lies on the conveyor. After setup 1 the operator turns the section over, 180° about its long axis, and runs setup 2: it cuts only that bevel, on the turned section (a channel&apos;s web and an angle&apos;s vertical leg change sides; the mitres are mirrored in the cell). Setup 2 without a K groove on the flanges has nothing to cut and is refused.</source>
        <translation>end_cut.setup - 1: das Profil wie aufgelegt, Unterseite auf dem Rollgang: das Ende wird geschnitten und jede für die Brenner erreichbare Fläche angefast. Eine K-Fuge (Doppelfase) an den Flanschen braucht auch eine Fase an der Unterseite des Unterflanschs (L-Winkel: waagr. Schenkel), der auf dem Rollgang liegt. Nach Aufspannung 1 wendet der Bediener das Profil um 180° um seine Längsachse und startet Aufspannung 2: sie schneidet nur diese Fase, am gewendeten Profil (der Steg eines U-Profils und der senkrechte Schenkel eines L-Winkels wechseln die Seite; die Gehrungen werden in der Zelle gespiegelt). Aufspannung 2 ohne K-Fuge an den Flanschen hat nichts zu schneiden und wird abgelehnt.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>No K groove on the flanges: setup 1 cuts the whole end.</source>
        <translation>Keine K-Fuge an den Flanschen: Aufspannung 1 schneidet das ganze Ende.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setup 2 of 2: the section lies turned over; only the bevel on the underside of the bottom flange (angles: horizontal leg), now on top, is cut.</source>
        <translation>Aufspannung 2 von 2: das Profil liegt gewendet; nur die Fase an der Unterseite des Unterflanschs (L-Winkel: waagr. Schenkel), jetzt oben, wird geschnitten.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setup 1 of 2: the underside of the bottom flange (angles: horizontal leg) lies on the conveyor. Then turn the section over and run setup 2.</source>
        <translation>Aufspannung 1 von 2: die Unterseite des Unterflanschs (L-Winkel: waagr. Schenkel) liegt auf dem Rollgang. Danach das Profil wenden und Aufspannung 2 starten.</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::SectionSteelSectionForm</name>
    <message>
        <location line="-321"/>
        <source>L (equal legs)</source>
        <translation>L (gleichschenklig)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>L (unequal legs)</source>
        <translation>L (ungleichschenklig)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>User-defined dimensions</source>
        <translation>Benutzerdefinierte Maße</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The section lies on the cutting table along x, its underside on the table; the end at x = 0 is cut. Catalogue dimensions after EN 10365:2017 (IPE, HEA, HEB, UPN, UPE) and EN 10056-1:2017 (angles); the root radii are drawn and cut.</source>
        <translation>Das Profil liegt längs x auf dem Schneidtisch, mit der Unterseite auf dem Tisch; das Ende bei x = 0 wird geschnitten. Katalogmaße nach EN 10365:2017 (IPE, HEA, HEB, UPN, UPE) und EN 10056-1:2017 (Winkel); die Ausrundungsradien werden gezeichnet und geschnitten.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Section</source>
        <translation>Profil</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Series</source>
        <translation>Reihe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Designation</source>
        <translation>Bezeichnung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>I / H section</source>
        <translation>I-/H-Profil</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>U channel</source>
        <translation>U-Profil</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>L angle</source>
        <translation>L-Winkel</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Shape (user-defined)</source>
        <translation>Form (benutzerdef.)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Height h (L: vertical leg)</source>
        <translation>Höhe h (L: senkr. Schenkel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Width b (L: horizontal leg)</source>
        <translation>Breite b (L: waagr. Schenkel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Web thickness tw (L: leg)</source>
        <translation>Stegdicke tw (L: Schenkel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flange thickness tf (L: leg)</source>
        <translation>Flanschdicke tf (L: Schenkel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Root radius r</source>
        <translation>Ausrundung r</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Toe radius r2 (U, L)</source>
        <translation>Kantenradius r2 (U, L)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bar length</source>
        <translation>Stablänge</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Piece (from the detailing software)</source>
        <translation>Teil (aus der Konstruktionssoftware)</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Order %1, drawing %2, phase %3, piece mark %4, steel %5, quantity %6 (the job cuts one piece)</source>
        <translation>Auftrag %1, Zeichnung %2, Phase %3, Positionsnummer %4, Stahl %5, Stückzahl %6 (der Auftrag schneidet ein Teil)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>User-defined dimensions: checked against the section&apos;s own limits (the root radius must leave a flat flange).</source>
        <translation>Benutzerdefinierte Maße: geprüft gegen die Grenzen des Profils (der Ausrundungsradius muss einen ebenen Flansch übrig lassen).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 from the catalogue (%2 shape): the dimensions are the standard&apos;s; choose &quot;User-defined dimensions&quot; to change them.</source>
        <translation>%1 aus dem Katalog (Form %2): die Maße sind die der Norm; zum Ändern &quot;Benutzerdefinierte Maße&quot; wählen.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The section&apos;s thickest plate: the flange or the web, whichever is thicker.</source>
        <translation>Das dickste Blech des Profils: Flansch oder Steg, je nachdem, welches dicker ist.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Not used: the section-steel cutter takes only the kerf width from the cut chart.</source>
        <translation>Nicht verwendet: Die Profilstahl-Schneidanlage übernimmt aus der Schneidtabelle nur die Schnittfugenbreite.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Not used: the section-steel cutter cuts at its own speed (Cutting speed along the outline, on the Motion &amp; arms page).</source>
        <translation>Nicht verwendet: Die Profilstahl-Schneidanlage schneidet mit ihrer eigenen Geschwindigkeit (Schnittgeschw. entlang der Kontur, Seite Bewegung &amp; Arme).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No cut chart: the cut runs without kerf compensation.</source>
        <translation>Keine Schneidtabelle: der Schnitt läuft ohne Schnittfugenkorrektur.</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::StateLamps</name>
    <message>
        <location filename="../../ui/panels/state_lamps.cpp" line="+67"/>
        <source>Ready</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Running</source>
        <translation>Läuft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Paused</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E-STOP</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torch</source>
        <translation>Brenner</translation>
    </message>
</context>
<context>
    <name>CutCell::ui::WindowHost</name>
    <message>
        <location filename="../../ui/window_host.cpp" line="+34"/>
        <location line="+7"/>
        <source>The language was not changed: %1.</source>
        <translation>Die Sprache wurde nicht gewechselt: %1.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Language: %1.</source>
        <translation>Sprache: %1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The drives were disabled for the change of language: press Enable and Home.</source>
        <translation>Für den Sprachwechsel wurden die Antriebe gesperrt: Freigeben und Referenzieren drücken.</translation>
    </message>
</context>
<context>
    <name>GuiLanguage</name>
    <message>
        <location filename="../../ui/language.cpp" line="+61"/>
        <source>System (%1)</source>
        <translation>System (%1)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>unknown language &quot;%1&quot; (known: en, de)</source>
        <translation>unbekannte Sprache &quot;%1&quot; (bekannt: en, de)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the %1 catalogue is missing from this build</source>
        <translation>der Katalog %1 fehlt in diesem Build</translation>
    </message>
</context>
<context>
    <name>HelpMenu</name>
    <message>
        <location filename="../../ui/help_menu.cpp" line="+17"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Keys</source>
        <translation>&amp;Tasten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keys</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Manual</source>
        <translation>&amp;Handbuch</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;About CutCell</source>
        <translation>&amp;Über CutCell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About CutCell</source>
        <translation>Über CutCell</translation>
    </message>
</context>
<context>
    <name>HelpTexts</name>
    <message>
        <location filename="../../ui/help_texts.cpp" line="+40"/>
        <source>&lt;h3&gt;CutCell operator station %1&lt;/h3&gt;&lt;p&gt;Build: %2 (%3), %4, %5&lt;br&gt;Qt %6 (built with %7)&lt;br&gt;Language: %8&lt;/p&gt;&lt;p&gt;Machines in this build:&lt;/p&gt;&lt;ul&gt;&lt;li&gt;%9&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;The manual (Help &amp;rarr; Manual) is the README&apos;s operator sections of this build.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;CutCell Bedienstation %1&lt;/h3&gt;&lt;p&gt;Build: %2 (%3), %4, %5&lt;br&gt;Qt %6 (gebaut mit %7)&lt;br&gt;Sprache: %8&lt;/p&gt;&lt;p&gt;Maschinen in diesem Build:&lt;/p&gt;&lt;ul&gt;&lt;li&gt;%9&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Das Handbuch (Hilfe &amp;rarr; Handbuch) sind die Bedienabschnitte der README dieses Builds (auf Englisch).&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>CutCell manual: the operator station</source>
        <translation>CutCell-Handbuch: die Bedienstation</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The manual is missing from this build (README.md).</source>
        <translation>Das Handbuch fehlt in diesem Build (README.md).</translation>
    </message>
</context>
<context>
    <name>IssueText</name>
    <message>
        <location filename="../../ui/forms/issue_text.cpp" line="+17"/>
        <source>%1 is not a finite number: it must lie in [%2, %3] %4</source>
        <translation>%1 ist keine endliche Zahl: erlaubt sind %2 bis %3 %4</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 = %2 %3 is outside [%4, %5] %3</source>
        <translation>%1 = %2 %3 liegt außerhalb von %4 bis %5 %3</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../../ui/job_import.cpp" line="+25"/>
        <source>No importer &quot;%1&quot; in this build.</source>
        <translation>Kein Import &quot;%1&quot; in dieser Version.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot import %1: %2</source>
        <translation>%1 kann nicht importiert werden: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 files (%2);;All files (*)</source>
        <translation>%1-Dateien (%2);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Import %1...</source>
        <translation>%1 importieren...</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+19"/>
        <source>Import report</source>
        <translation>Importbericht</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>%1: imported; the job does everything the file asks.</source>
        <translation>%1: importiert; der Auftrag setzt alles um, was die Datei verlangt.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%1: imported. %n thing(s) of the file the job does not do (also in the event log):</source>
        <translation>
            <numerusform>%1: importiert. %n Angabe der Datei setzt der Auftrag nicht um (auch im Ereignisprotokoll):</numerusform>
            <numerusform>%1: importiert. %n Angaben der Datei setzt der Auftrag nicht um (auch im Ereignisprotokoll):</numerusform>
        </translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 file(s): %2 imported, %3 refused. The jobs and import-report.csv are in %4.</source>
        <translation>%1 Datei(en): %2 importiert, %3 abgelehnt. Die Aufträge und import-report.csv liegen in %4.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Refused because</source>
        <translation>Abgelehnt, weil</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>imported</source>
        <translation>importiert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>refused</source>
        <translation>abgelehnt</translation>
    </message>
    <message>
        <location filename="../../ui/machine/machine_choice.cpp" line="+19"/>
        <source>New job</source>
        <translation>Neuer Auftrag</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Machine for the new job:</source>
        <translation>Maschine für den neuen Auftrag:</translation>
    </message>
    <message>
        <location filename="../../ui/machine/machine_ui_registry.cpp" line="+107"/>
        <source>Export &amp;G-code...</source>
        <translation>&amp;G-code exportieren...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export template (SVG)...</source>
        <translation>Schablone exportieren (SVG)...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export template (PDF)...</source>
        <translation>Schablone exportieren (PDF)...</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>G-code (*.ngc *.nc *.gcode)</source>
        <translation>G-code (*.ngc *.nc *.gcode)</translation>
    </message>
    <message>
        <location filename="../../ui/machine_exports.cpp" line="+23"/>
        <source>Export to %1 failed: %2</source>
        <translation>Export nach %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no machine module for machine = &quot;%1&quot;</source>
        <translation>kein Maschinenmodul für machine = &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the %1 offers no &quot;%2&quot; export</source>
        <translation>die Maschine %1 bietet keinen Export &quot;%2&quot;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>paper &quot;%1&quot; is not single, A4 or A3</source>
        <translation>Papier &quot;%1&quot; ist weder single, A4 noch A3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>cutting template (%1, 1:1): %2 x %3 mm</source>
        <translation>Schneidschablone (%1, 1:1): %2 x %3 mm</translation>
    </message>
    <message>
        <location line="+12"/>
        <source> on %1 sheets of %2 %3 (%4 x %5)</source>
        <translation> auf %1 Blatt %2 %3 (%4 x %5)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>landscape</source>
        <translation>quer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>portrait</source>
        <translation>hoch</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Exported %1 to %2</source>
        <translation>%1 nach %2 exportiert</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Export to %1 refused: the job has invalid fields.</source>
        <translation>Export nach %1 abgelehnt: der Auftrag hat ungültige Felder.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>&amp;Single sheet (template size)...</source>
        <translation>&amp;Einzelblatt (Schablonengröße)...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A&amp;4 tiles (1:1, alignment crosses)...</source>
        <translation>A&amp;4-Kacheln (1:1, Passkreuze)...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A&amp;3 tiles (1:1, alignment crosses)...</source>
        <translation>A&amp;3-Kacheln (1:1, Passkreuze)...</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Export cut</source>
        <translation>Schnitt &amp;exportieren</translation>
    </message>
    <message>
        <location filename="../../ui/machines/flying_saw/flying_saw_ui.cpp" line="+22"/>
        <source>Flying saw on a welded-pipe line (carriage, turntable, 2 blade feeds)</source>
        <translation>Fliegende Säge an einer Rohrschweißanlage (Wagen, Drehtisch, 2 Blattvorschübe)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Tube &amp;&amp; line</source>
        <translation>Rohr &amp;&amp; Anlage</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Carriage &amp;&amp; saw</source>
        <translation>Wagen &amp;&amp; Säge</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cycle &amp;&amp; cuts</source>
        <translation>Zyklus &amp;&amp; Schnitte</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The flying saw cuts the tube of its line across: its tube, line and lengths are set on the Tube &amp; line page.</source>
        <translation>Die fliegende Säge trennt das Rohr ihrer Anlage quer: Rohr, Anlage und Längen werden auf der Seite Rohr &amp; Anlage eingestellt.</translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../../ui/machines/pipe_robot/pipe_robot_ui.cpp" line="+77"/>
        <location filename="../../ui/machines/profile_cutter/profile_cutter_ui.cpp" line="+99"/>
        <location filename="../../ui/machines/quick_return/quick_return_ui.cpp" line="+49"/>
        <location filename="../../ui/machines/section_steel/section_steel_ui.cpp" line="+47"/>
        <source>3D view not built in this configuration.</source>
        <translation>3D-Ansicht in dieser Konfiguration nicht enthalten.</translation>
    </message>
    <message>
        <location filename="../../ui/machines/pipe_robot/method_form.cpp" line="-27"/>
        <source>Static pipe: the chuck holds the pipe at a fixed angle and the arm follows the whole saddle curve around it.</source>
        <translation>Stehendes Rohr: das Futter hält das Rohr unter festem Winkel, und der Arm fährt die gesamte Sattelkurve um das Rohr ab.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rotating pipe: the chuck turns the pipe so that the cut point stays on top; the torch moves on a short straight line.</source>
        <translation>Drehendes Rohr: das Futter dreht das Rohr so, dass der Schnittpunkt oben bleibt; der Brenner fährt auf einer kurzen Geraden.</translation>
    </message>
    <message>
        <location filename="../../ui/machines/pipe_robot/pipe_robot_ui.cpp" line="-59"/>
        <source>Pipe-cutting robot: 5-DOF arm + pipe chuck (6 axes)</source>
        <translation>Rohrschneidroboter: 5-achsiger Arm + Rohrfutter (6 Achsen)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Method</source>
        <translation>Verfahren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Robot</source>
        <translation>Roboter</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../../ui/machines/quick_return/quick_return_ui.cpp" line="-24"/>
        <source>Controller</source>
        <translation>Regler</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Planned %1 points, %2 mm in %3 s (max. torch tilt %4 deg).</source>
        <translation>%1 Punkte geplant, %2 mm in %3 s (max. Brennerneigung %4 deg).</translation>
    </message>
    <message>
        <location filename="../../ui/machines/profile_cutter/profile_cutter_ui.cpp" line="-72"/>
        <source>2-axis NC pipe profile cutter: chuck A + carriage X</source>
        <translation>2-Achs-NC-Rohrprofilschneidmaschine: Futter A + Wagen X</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Profile cutter</source>
        <translation>Profilschneider</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The profile cutter&apos;s torch stands radial: no bevel.</source>
        <translation>Der Brenner des Profilschneiders steht radial: keine Fase.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The profile cutter&apos;s torch never tilts: no deviation limit.</source>
        <translation>Der Brenner des Profilschneiders neigt sich nie: keine Abweichungsgrenze.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>G-code (X/A): %1 moves, %2 mm developed, %3 s</source>
        <translation>G-code (X/A): %1 Bewegungen, %2 mm abgewickelt, %3 s</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Profile cutter: %1 points, %2 mm in %3 s.</source>
        <translation>Profilschneider: %1 Punkte, %2 mm in %3 s.</translation>
    </message>
    <message>
        <location filename="../../ui/machines/quick_return/quick_return_ui.cpp" line="-7"/>
        <source>Quick-return (Whitworth) cutter: crank in torque mode</source>
        <translation>Schnellrücklauf-Schneidmaschine (Whitworth): Kurbel in Momentenregelung</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Mechanism</source>
        <translation>Mechanik</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cut figures</source>
        <translation>Schnittdiagramme</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Experiment 1</source>
        <translation>Versuch 1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The quick-return cutter planes a flat workpiece along its stroke: no pipes, its cut is set on the Mechanism page.</source>
        <translation>Die Schnellrücklauf-Maschine hobelt ein flaches Werkstück entlang ihres Hubs: keine Rohre, ihr Schnitt wird auf der Seite Mechanik eingestellt.</translation>
    </message>
    <message>
        <location filename="../../ui/machines/section_steel/section_steel_ui.cpp" line="-30"/>
        <source>Section-steel cutter (3R path arm + 5-DOF groove arm)</source>
        <translation>Profilstahl-Schneidanlage (3R-Bahnarm + 5-achsiger Fasenarm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Section</source>
        <translation>Profil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>End cut</source>
        <translation>Endschnitt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Motion &amp;&amp; arms</source>
        <translation>Bewegung &amp;&amp; Arme</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drives</source>
        <translation>Antriebe</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The section-steel cutter cuts the end of a structural section: no pipes; its section, cut and speed are set on the Section, End cut and Motion pages.</source>
        <translation>Die Profilstahl-Schneidanlage schneidet das Ende eines Stahlprofils: keine Rohre; Profil, Schnitt und Geschwindigkeit werden auf den Seiten Profil, Endschnitt und Bewegung eingestellt.</translation>
    </message>
    <message>
        <location filename="../../ui/panels/alarm_panel.cpp" line="-242"/>
        <source>active, ack.</source>
        <translation>aktiv, quitt.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ACTIVE</source>
        <translation>AKTIV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>past, ack.</source>
        <translation>gegangen, quitt.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>past</source>
        <translation>gegangen</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="+222"/>
        <source>Cannot open the job</source>
        <translation>Auftrag kann nicht geöffnet werden</translation>
    </message>
</context>
<context>
    <name>RunWords</name>
    <message>
        <location filename="../../ui/panels/run_words.cpp" line="+26"/>
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parts</source>
        <translation>Teile</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pierce</source>
        <translation>Einstich</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>pierces</source>
        <translation>Einstiche</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Piece</source>
        <translation>Stück</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+2"/>
        <source>piece</source>
        <translation>Stück</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+1"/>
        <source>pieces</source>
        <translation>Stück</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Pieces</source>
        <translation>Stück</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stroke</source>
        <translation>Hub</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+2"/>
        <source>stroke</source>
        <translation>Hub</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+1"/>
        <source>strokes</source>
        <translation>Hübe</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Strokes</source>
        <translation>Hübe</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>torch</source>
        <translation>Brenner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>saw</source>
        <translation>Säge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cutter</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Idle</source>
        <translation>Inaktiv</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ready</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Homing</source>
        <translation>Referenzieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Jogging</source>
        <translation>Tippen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Running</source>
        <translation>Läuft</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Feed hold</source>
        <translation>Vorschub halt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Completed</source>
        <translation>Beendet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Emergency stop</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>point %1 / %2, %3 of %4 mm</source>
        <translation>Punkt %1 / %2, %3 von %4 mm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 %2 of %3, %4 %5 made</source>
        <translation>%1 %2 von %3, %4 %5 erledigt</translation>
    </message>
</context>
<context>
    <name>SectionField</name>
    <message>
        <location filename="core_labels.cpp" line="+13"/>
        <source>Tube</source>
        <translation>Rohr</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diameter D</source>
        <translation>Durchmesser D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Width a (across)</source>
        <translation>Breite a (waagr.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height b (up)</source>
        <translation>Höhe b (senkr.)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Corner radius r</source>
        <translation>Eckenradius r</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wall</source>
        <translation>Wandstärke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Line speed</source>
        <translation>Liniengeschw.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roller encoder</source>
        <translation>Rollengeber</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roller diameter</source>
        <translation>Rollendurchmesser</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Master filter gain α</source>
        <translation>Leitachs-Filterfaktor α</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Queue of lengths</source>
        <translation>Schnittliste</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length tolerance ±</source>
        <translation>Längentoleranz ±</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First sync-in at</source>
        <translation>1. Gleichlauf bei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stroke</source>
        <translation>Hub</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed limit</source>
        <translation>Max. Geschw.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration limit</source>
        <translation>Max. Beschleunigung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jerk limit</source>
        <translation>Max. Ruck</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wait position</source>
        <translation>Warteposition</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Settle C → D</source>
        <translation>Einschwingen C → D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fast feed (in air)</source>
        <translation>Eilvorschub (in Luft)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slow feed (through the wall)</source>
        <translation>Schnittvorschub (durch die Wand)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fast feed stops before the tube</source>
        <translation>Eilvorschub endet vor dem Rohr</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overcut past the bore</source>
        <translation>Überschnitt in die Bohrung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retracted clearance</source>
        <translation>Abstand in Rückzugslage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retract speed</source>
        <translation>Rückzugsgeschw.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turntable speed</source>
        <translation>Drehtellergeschw.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turntable acceleration</source>
        <translation>Drehtellerbeschleunigung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cam table points</source>
        <translation>Punkte Kurventabelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diameter</source>
        <translation>Durchmesser</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kerf</source>
        <translation>Schnittbreite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed</source>
        <translation>Drehzahl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length gauge</source>
        <translation>Längenmessung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gauge delay</source>
        <translation>Messverzug</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gauge noise ±</source>
        <translation>Messrauschen ±</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Correction gain</source>
        <translation>Korrekturfaktor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed wander</source>
        <translation>Geschw.-Schwankung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wander frequency</source>
        <translation>Schwankungsfrequenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed step</source>
        <translation>Geschw.-Sprung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mean time between steps</source>
        <translation>Mittlerer Sprungabstand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step ramp</source>
        <translation>Sprungrampe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reading noise ±</source>
        <translation>Geberrauschen ±</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roller slip</source>
        <translation>Rollenschlupf</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Random seed</source>
        <translation>Zufallsstartwert</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Steps per revolution (n)</source>
        <translation>Schritte pro Umdrehung (n)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pulses per step</source>
        <translation>Impulse pro Schritt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Travel per pulse</source>
        <translation>Weg pro Impuls</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max. pulse rate per axis</source>
        <translation>Max. Impulsrate je Achse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pierce dwell</source>
        <translation>Einstechzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Carriage travel</source>
        <translation>Verfahrweg Schlitten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Branch axis at X (S)</source>
        <translation>Abzweigachse bei X (S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rocker pivot O3x</source>
        <translation>Schwingenlager O3x</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rocker pivot O3y</source>
        <translation>Schwingenlager O3y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Crank r2</source>
        <translation>Kurbel r2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A to B on the rocker (AB)</source>
        <translation>A bis B auf der Schwinge (AB)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link r4</source>
        <translation>Koppel r4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slider line Dx</source>
        <translation>Schieberbahn Dx</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scale offset</source>
        <translation>Maßstabsoffset</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slider mass m5</source>
        <translation>Schiebermasse m5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scale resolution</source>
        <translation>Maßstabsauflösung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Crank inertia</source>
        <translation>Kurbelträgheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rocker inertia</source>
        <translation>Schwingenträgheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Viscous friction</source>
        <translation>Viskose Reibung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coulomb friction</source>
        <translation>Coulomb-Reibung</translation>
    </message>
    <message>
        <location line="-84"/>
        <source>Torque limit</source>
        <translation>Momentgrenze</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>Kp</source>
        <translation>Kp</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ki</source>
        <translation>Ki</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kd</source>
        <translation>Kd</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tau_f</source>
        <translation>tau_f</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inertia</source>
        <translation>Trägheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Viscous</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>mass</source>
        <translation>Masse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>com x</source>
        <translation>SP x</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>com y</source>
        <translation>SP y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>com z</source>
        <translation>SP z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ixx</source>
        <translation>Ixx</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Iyy</source>
        <translation>Iyy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Izz</source>
        <translation>Izz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ixy</source>
        <translation>Ixy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ixz</source>
        <translation>Ixz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Iyz</source>
        <translation>Iyz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gear N</source>
        <translation>Getriebe N</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rotor J</source>
        <translation>Rotor J</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>viscous</source>
        <translation>viskos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coulomb</source>
        <translation>Coulomb-Reibung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torque limit</source>
        <translation>Momentgrenze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>alpha</source>
        <translation>alpha</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a</source>
        <translation>a</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>d</source>
        <translation>d</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Workpiece length L_d</source>
        <translation>Werkstücklänge L_d</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stroke L_c</source>
        <translation>Hub L_c</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cutting velocity v</source>
        <translation>Schnittgeschw. v</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Contact force</source>
        <translation>Kontaktkraft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Strokes</source>
        <translation>Hübe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Return torque, first half</source>
        <translation>Rücklaufmoment, 1. Hälfte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Return torque, second half</source>
        <translation>Rücklaufmoment, 2. Hälfte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ω</source>
        <translation>ω</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MSE window</source>
        <translation>MSE-Fenster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MSE scale L</source>
        <translation>MSE-Faktor L</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Experiment</source>
        <translation>Experiment</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller</source>
        <translation>Regler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sample time</source>
        <translation>Abtastzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jacobian</source>
        <translation>Jacobi-Matrix</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>K_ρ</source>
        <translation>K_ρ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model slider mass</source>
        <translation>Schiebermasse Modell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disturbance amplitude</source>
        <translation>Störamplitude</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disturbance frequency</source>
        <translation>Störfrequenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ω_n²</source>
        <translation>ω_n²</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ξ</source>
        <translation>ξ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>q1</source>
        <translation>q1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>q2</source>
        <translation>q2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>c</source>
        <translation>c</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>η</source>
        <translation>η</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>φ</source>
        <translation>φ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>q11</source>
        <translation>q11</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>q12</source>
        <translation>q12</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>q22</source>
        <translation>q22</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>λ</source>
        <translation>λ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>k1</source>
        <translation>k1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>k2</source>
        <translation>k2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About the vertical axis (z)</source>
        <translation>Um die senkrechte Achse (z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About the horizontal axis (y)</source>
        <translation>Um die waagrechte Achse (y)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flange groove</source>
        <translation>Fuge Flansch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flange bevel angle</source>
        <translation>Fasenwinkel Flansch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flange root face</source>
        <translation>Steghöhe Flansch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Web groove</source>
        <translation>Fuge Steg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Web bevel angle</source>
        <translation>Fasenwinkel Steg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Web root face</source>
        <translation>Steghöhe Steg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setup</source>
        <translation>Aufspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cutting speed along the outline</source>
        <translation>Schnittgeschw. entlang der Kontur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp to and from the speed</source>
        <translation>Anfahr-/Bremsrampe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Knot spacing</source>
        <translation>Stützpunktabstand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torch turn at the toes</source>
        <translation>Brennerschwenk an Kanten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bevel blend per face</source>
        <translation>Fasenübergang je Fläche</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torch length (collision check)</source>
        <translation>Brennerlänge (Kollisionsprüfung)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torch body radius</source>
        <translation>Radius Brennerkörper</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest lean along the cut edge</source>
        <translation>Max. Neigung längs der Schnittkante</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base y</source>
        <translation>Basis y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base z (above the table)</source>
        <translation>Basis z (über dem Tisch)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Path arm links</source>
        <translation>Glieder Bahnarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Path arm joint limits</source>
        <translation>Gelenkgrenzen Bahnarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base x (past the cut)</source>
        <translation>Basis x (hinter Schnitt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base z</source>
        <translation>Basis z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Groove arm joint limits</source>
        <translation>Gelenkgrenzen Fasenarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Park position</source>
        <translation>Parkposition</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drives</source>
        <translation>Antriebe</translation>
    </message>
</context>
<context>
    <name>SectionSteelScene</name>
    <message>
        <location filename="../../ui/machines/section_steel/section_steel_scene.cpp" line="+121"/>
        <source>Section-steel cutter</source>
        <translation>Profilstahl-Schneidanlage</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>setup 2: the section turned over</source>
        <translation>Aufspannung 2: das Profil gewendet</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>NOT feasible:</source>
        <translation>NICHT ausführbar:</translation>
    </message>
</context>
<context>
    <name>SectionUnit</name>
    <message>
        <location filename="core_labels.cpp" line="+1"/>
        <source>pulses/rev</source>
        <translation>Imp./U</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pieces</source>
        <translation>Stück</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steps/rev</source>
        <translation>Schritte/U</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pulses/step</source>
        <translation>Imp./Schritt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mm/pulse</source>
        <translation>mm/Imp.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>strokes</source>
        <translation>Hübe</translation>
    </message>
</context>
<context>
    <name>cutcell::app::ShopfloorSettingsDialog</name>
    <message>
        <location filename="../../app/gui/shopfloor_settings.cpp" line="+69"/>
        <source>Log in to change the shop-floor link&apos;s settings (needs the %1 level)</source>
        <translation>Zum Ändern der Werkstattverbindung anmelden (erfordert die Stufe %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The shop-floor link&apos;s settings need the %1 level (%2 is logged in as %3)</source>
        <translation>Die Einstellungen der Werkstattverbindung erfordern die Stufe %1 (%2 ist als %3 angemeldet)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Link on: publish the cell&apos;s state, take jobs from the network</source>
        <translation>Verbindung an: Zustand der Zelle veröffentlichen, Aufträge aus dem Netz annehmen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shop-floor link</source>
        <translation>Werkstattverbindung</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Key in the file: %1</source>
        <translation>Schlüssel in der Datei: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>messages</source>
        <translation>Nachrichten</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Broker host</source>
        <translation>Broker-Rechner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Broker port</source>
        <translation>Broker-Port</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sparkplug group id</source>
        <translation>Sparkplug-Gruppenkennung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edge node id (this cell)</source>
        <translation>Edge-Node-Kennung (diese Zelle)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>User name</source>
        <translation>Benutzername</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Password file</source>
        <translation>Passwortdatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CA certificate file</source>
        <translation>CA-Zertifikatsdatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Client certificate file</source>
        <translation>Client-Zertifikatsdatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Client key file</source>
        <translation>Client-Schlüsseldatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Axis positions rate</source>
        <translation>Rate der Achspositionen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Store-and-forward capacity</source>
        <translation>Zwischenspeicher (Store and Forward)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep-alive</source>
        <translation>Keep-alive</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The password itself is never stored here: the password file&apos;s first line is the password (readable by its owner only, chmod 600). Relative file names are read from the folder of %1.</source>
        <translation>Das Passwort selbst wird hier nie gespeichert: Die erste Zeile der Passwortdatei ist das Passwort (nur für ihren Besitzer lesbar, chmod 600). Relative Dateinamen gelten im Ordner von %1.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Check, write %1 and restart the link with it</source>
        <translation>Prüfen, %1 schreiben und die Verbindung damit neu starten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The file cannot be read (%1): the fields show the defaults; Save replaces it.</source>
        <translation>Die Datei ist nicht lesbar (%1): Die Felder zeigen die Vorgaben; Speichern ersetzt sie.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the file</source>
        <translation>Datei wählen</translation>
    </message>
    <message>
        <location line="+63"/>
        <location line="+7"/>
        <location line="+18"/>
        <source>Not saved: %1</source>
        <translation>Nicht gespeichert: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved to %1. %2</source>
        <translation>Gespeichert in %1. %2</translation>
    </message>
</context>
<context>
    <name>cutcell::plots::HistoryChartsWidget</name>
    <message>
        <location filename="../../plots/history_charts_widget.cpp" line="+46"/>
        <source>Cycle time per run</source>
        <translation>Zykluszeit je Lauf</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>cycle time (s)</source>
        <translation>Zykluszeit (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alarms (Pareto)</source>
        <translation>Alarme (Pareto)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cumulative (%)</source>
        <translation>kumuliert (%)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>completed</source>
        <translation>fertig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped short</source>
        <translation>vorzeitig angehalten</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>other</source>
        <translation>übrige</translation>
    </message>
</context>
<context>
    <name>cutcell::plots::TrackingPlotsWidget</name>
    <message>
        <location filename="../../plots/tracking_plots_widget.cpp" line="+220"/>
        <source>error (%1)</source>
        <translation>Schleppfehler (%1)</translation>
    </message>
    <message>
        <location line="+161"/>
        <source>%1 samples, %2 dropped</source>
        <translation>%1 Messwerte, %2 verworfen</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Freeze the plots; data keeps being recorded</source>
        <translation>Diagramme einfrieren; die Daten werden weiter aufgezeichnet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Autoscale both plots and follow the data</source>
        <translation>Beide Diagramme automatisch skalieren und den Daten folgen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Legend</source>
        <translation>Legende</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show or hide the trace names above the plots</source>
        <translation>Kurvennamen über den Diagrammen ein- oder ausblenden</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Export PNG...</source>
        <translation>PNG exportieren...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export plots as PNG</source>
        <translation>Diagramme als PNG exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export PNG</source>
        <translation>PNG exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export CSV...</source>
        <translation>CSV exportieren...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export errors as CSV</source>
        <translation>Schleppfehler als CSV exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export CSV</source>
        <translation>CSV exportieren</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cartesian error (mm)</source>
        <translation>Kartesischer Fehler (mm)</translation>
    </message>
    <message>
        <location line="+166"/>
        <source>Cannot write the PNG file &apos;%1&apos;: %2</source>
        <translation>PNG-Datei &apos;%1&apos; kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+28"/>
        <source>Cannot write the CSV file &apos;%1&apos;: %2</source>
        <translation>CSV-Datei &apos;%1&apos; kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>cutcell::ui::DevicePanel</name>
    <message>
        <location filename="../../ui/device_panel.cpp" line="+23"/>
        <source>Simulated drives (in-process)</source>
        <translation>Simulierte Antriebe (intern)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CANopen CiA 402 drives</source>
        <translation>Antriebe CANopen CiA 402</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Qt CAN plugin: socketcan on a real bus, virtualcan for tests</source>
        <translation>Qt-CAN-Plugin: socketcan am realen Bus, virtualcan für Tests</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+10"/>
        <source>Bit rate</source>
        <translation>Bitrate</translation>
    </message>
    <message>
        <location line="-7"/>
        <source> kbit/s</source>
        <translation> kbit/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Drives</source>
        <translation>Antriebe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN plugin</source>
        <translation>CAN-Plugin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Interface</source>
        <translation>Schnittstelle</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bus: -</source>
        <translation>Bus: -</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load: -</source>
        <translation>Buslast: -</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMT</source>
        <translation>NMT</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CiA 402</source>
        <translation>CiA 402</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heartbeat</source>
        <translation>Heartbeat</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Last EMCY</source>
        <translation>Letzte EMCY</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Fault reset</source>
        <translation>Störungsreset</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>Bus: none (simulated in-process drives)</source>
        <translation>Bus: keiner (simulierte interne Antriebe)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bus: %1</source>
        <translation>Bus: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Load: %1 %</source>
        <translation>Buslast: %1 %</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
</context>
<context>
    <name>cutcell::view3d::CellView</name>
    <message>
        <location filename="../../ui/view3d/cell_view.cpp" line="+56"/>
        <source>ON</source>
        <translation>EIN</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>points reachable</source>
        <translation>Punkte erreichbar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>points NOT reachable (red)</source>
        <translation>Punkte NICHT erreichbar (rot)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Iso</source>
        <translation>Iso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Front</source>
        <translation>Vorne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Top</source>
        <translation>Oben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Follow tool</source>
        <translation>Werkzeug folgen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Reset view</source>
        <translation>Grundansicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Back to the iso view of the whole cell</source>
        <translation>Zurück zur Iso-Ansicht der ganzen Zelle</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>3D view unavailable: no OpenGL on this platform (offscreen)</source>
        <translation>3D-Ansicht nicht verfügbar: kein OpenGL auf dieser Plattform (offscreen)</translation>
    </message>
</context>
</TS>
