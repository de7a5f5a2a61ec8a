package eu.brain.iot.bms.impl;

import java.util.List;

/**
 * An install request in flight and the event types waiting for it. Owned by the BMS's thread, which alone adds to
 * {@code types}.
 *
 * @param id identifies the request (several types, and a revival, may share it)
 * @param symbolicName the behaviour's bundle symbolic name: the installer turns requests for one name into one install,
 *        and so does the BMS
 * @param behaviour "symbolicName version", as the history and the types' states name it
 * @param kind the history's word for its success: {@code INSTALLED}, {@code RESTARTED} (it was installed but not
 *        active) or {@code REINSTALLED} (its bundle had been uninstalled by someone else)
 * @param reason what the request told the installer (its journal records it)
 * @param types the event types whose held events wait for it
 * @param revival {@code true} when {@link Revivals} asked for it (its bundle stopped or was uninstalled outside the
 *        installer) rather than an event
 */
record InstallJob(long id, String symbolicName, String behaviour, String kind, String reason, List<String> types,
        boolean revival) {
}
